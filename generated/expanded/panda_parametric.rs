// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/panda_parametric.json")` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "panda";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "Franka Emika Panda, 7R, hand lumped in, fingers locked closed, from the URDF of example-robot-data";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 7;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "armdyn-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/panda.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "0440096b89a0fdc54a9897902a543d66dd662bbf2fd04a072460e9ae58ce4453";
/// Joint names, base to tip.
pub const JOINT_NAMES: [&str; DOF] = [
    "panda_joint1",
    "panda_joint2",
    "panda_joint3",
    "panda_joint4",
    "panda_joint5",
    "panda_joint6",
    "panda_joint7",
];
/// `true` for a prismatic joint (m, N), `false` for a revolute one (rad, N m).
pub const JOINT_IS_PRISMATIC: [bool; DOF] = [
    false, false, false, false, false, false, false,
];
/// Joint position limits `[lower, upper]`, rad or m.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const JOINT_LIMITS: [[f64; 2]; DOF] = [
    [-2.8973_f64, 2.8973_f64],
    [-1.7628_f64, 1.7628_f64],
    [-2.8973_f64, 2.8973_f64],
    [-3.0718_f64, -0.0698_f64],
    [-2.8973_f64, 2.8973_f64],
    [-0.0175_f64, 3.7525_f64],
    [-2.8973_f64, 2.8973_f64],
];
/// Actuator effort limits, N m (revolute) or N (prismatic).
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const EFFORT_LIMITS: [f64; DOF] = [
    87.0_f64,
    87.0_f64,
    87.0_f64,
    87.0_f64,
    12.0_f64,
    12.0_f64,
    12.0_f64,
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
    ("mass_matrix", 544, 12),
    ("coriolis_matrix", 7600, 12),
    ("coriolis", 757, 12),
    ("gravity", 178, 12),
    ("inverse_dynamics", 792, 12),
    ("forward_dynamics", 1545, 12),
];
/// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
///
/// # Inputs
///
/// - `q: &[f64; 7]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 70]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `mass_matrix: [[f64; 7]; 7]` (7 x 7, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
///
/// Operation count: 544 floating-point operations, 12 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix(q: &[f64; 7], params: &[f64; 70]) -> [[f64; 7]; 7] {
    let (
        v0,
        v2,
        v3,
        v5,
        v6,
        v8,
        v9,
        v11,
        v14,
        v34,
        v40,
        v41,
        v48,
        v50,
        v60,
        v62,
        v66,
        v68,
        v71,
        v73,
        v75,
        v78,
        v80,
        v85,
        v86,
        v96,
        v97,
        v101,
        v104,
        v106,
        v112,
        v117,
        v119,
        v120,
        v128,
        v129,
        v131,
        v133,
        v138,
        v139,
        v140,
        v145,
        v148,
        v150,
        v151,
        v152,
        v156,
        v157,
        v178,
        v267,
        v348,
    ) = {
        let v0: f64 = params[9];
        let v1: f64 = q[1];
        let (v2, v348): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = params[14];
        let v4: f64 = q[2];
        let (v267, v5): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
        let v6: f64 = params[24];
        let v7: f64 = q[3];
        let (v178, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v7);
        let v9: f64 = params[34];
        let v10: f64 = q[4];
        let (v80, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v10);
        let v12: f64 = params[44];
        let v13: f64 = q[5];
        let (v50, v14): (f64, f64) = ::armdyn_runtime::libm::sincos(v13);
        let v15: f64 = params[54];
        let v16: f64 = q[6];
        let (v20, v17): (f64, f64) = ::armdyn_runtime::libm::sincos(v16);
        let v18: f64 = params[64];
        let v19: f64 = v17 * v18;
        let v21: f64 = params[65];
        let v22: f64 = v20 * v21;
        let v23: f64 = v19 - v22;
        let v24: f64 = v23 * v17;
        let v25: f64 = v17 * v21;
        let v26: f64 = params[67];
        let v27: f64 = v20 * v26;
        let v28: f64 = v25 - v27;
        let v29: f64 = v28 * v20;
        let v30: f64 = v24 - v29;
        let v31: f64 = 0.007743999999999999_f64;
        let v32: f64 = params[60];
        let v33: f64 = v31 * v32;
        let v34: f64 = 2.0_f64;
        let v35: f64 = 0.088_f64;
        let v36: f64 = params[61];
        let v37: f64 = v17 * v36;
        let v38: f64 = params[62];
        let v39: f64 = v20 * v38;
        let v40: f64 = v37 - v39;
        let v41: f64 = v35 * v40;
        let v42: f64 = v34 * v41;
        let v43: f64 = v33 + v42;
        let v44: f64 = v30 + v43;
        let v45: f64 = v44 - v33;
        let v46: f64 = v45 - v41;
        let v47: f64 = v46 - v41;
        let v48: f64 = v15 + v47;
        let v49: f64 = v14 * v48;
        let v51: f64 = params[55];
        let v52: f64 = params[68];
        let v53: f64 = v52 * v20;
        let v54: f64 = params[66];
        let v55: f64 = v54 * v17;
        let v56: f64 = v53 - v55;
        let v57: f64 = params[63];
        let v58: f64 = v35 * v57;
        let v59: f64 = v56 + v58;
        let v60: f64 = v51 + v59;
        let v61: f64 = v50 * v60;
        let v62: f64 = v49 - v61;
        let v63: f64 = v62 * v14;
        let v64: f64 = v17 * v54;
        let v65: f64 = v20 * v52;
        let v66: f64 = v64 - v65;
        let v67: f64 = v58 - v66;
        let v68: f64 = v51 + v67;
        let v69: f64 = v14 * v68;
        let v70: f64 = params[57];
        let v71: f64 = params[69];
        let v72: f64 = v71 + v43;
        let v73: f64 = v70 + v72;
        let v74: f64 = v50 * v73;
        let v75: f64 = v69 - v74;
        let v76: f64 = v75 * v50;
        let v77: f64 = v63 - v76;
        let v78: f64 = v12 + v77;
        let v79: f64 = v11 * v78;
        let v81: f64 = params[45];
        let v82: f64 = params[58];
        let v83: f64 = v20 * v54;
        let v84: f64 = v17 * v52;
        let v85: f64 = v83 + v84;
        let v86: f64 = v82 - v85;
        let v87: f64 = v86 * v50;
        let v88: f64 = params[56];
        let v89: f64 = v20 * v18;
        let v90: f64 = v89 + v25;
        let v91: f64 = v90 * v17;
        let v92: f64 = v17 * v26;
        let v93: f64 = v22 + v92;
        let v94: f64 = v93 * v20;
        let v95: f64 = v91 - v94;
        let v96: f64 = v20 * v36;
        let v97: f64 = v17 * v38;
        let v98: f64 = v96 + v97;
        let v99: f64 = v35 * v98;
        let v100: f64 = v95 - v99;
        let v101: f64 = v88 + v100;
        let v102: f64 = v101 * v14;
        let v103: f64 = v87 - v102;
        let v104: f64 = v81 + v103;
        let v105: f64 = v80 * v104;
        let v106: f64 = v79 - v105;
        let v107: f64 = v106 * v11;
        let v108: f64 = v23 * v20;
        let v109: f64 = v28 * v17;
        let v110: f64 = v108 + v109;
        let v111: f64 = v110 - v99;
        let v112: f64 = v88 + v111;
        let v113: f64 = v14 * v112;
        let v114: f64 = v54 * v20;
        let v115: f64 = v52 * v17;
        let v116: f64 = v114 + v115;
        let v117: f64 = v82 - v116;
        let v118: f64 = v50 * v117;
        let v119: f64 = v113 - v118;
        let v120: f64 = v81 - v119;
        let v121: f64 = v11 * v120;
        let v122: f64 = params[47];
        let v123: f64 = params[59];
        let v124: f64 = v90 * v20;
        let v125: f64 = v93 * v17;
        let v126: f64 = v124 + v125;
        let v127: f64 = v126 + v43;
        let v128: f64 = v123 + v127;
        let v129: f64 = v122 + v128;
        let v130: f64 = v80 * v129;
        let v131: f64 = v121 - v130;
        let v132: f64 = v131 * v80;
        let v133: f64 = v107 - v132;
        let v134: f64 = 0.15426225000000002_f64;
        let v135: f64 = params[40];
        let v136: f64 = params[50];
        let v137: f64 = v136 + v32;
        let v138: f64 = v135 + v137;
        let v139: f64 = v134 * v138;
        let v140: f64 = -0.0825_f64;
        let v141: f64 = params[41];
        let v142: f64 = params[51];
        let v143: f64 = v35 * v32;
        let v144: f64 = v40 + v143;
        let v145: f64 = v142 + v144;
        let v146: f64 = v14 * v145;
        let v147: f64 = params[52];
        let v148: f64 = v147 - v57;
        let v149: f64 = v50 * v148;
        let v150: f64 = v146 - v149;
        let v151: f64 = v141 + v150;
        let v152: f64 = v11 * v151;
        let v153: f64 = params[42];
        let v154: f64 = params[53];
        let v155: f64 = v154 + v98;
        let v156: f64 = v153 - v155;
        let v157: f64 = v80 * v156;
        (
            v0,
            v2,
            v3,
            v5,
            v6,
            v8,
            v9,
            v11,
            v14,
            v34,
            v40,
            v41,
            v48,
            v50,
            v60,
            v62,
            v66,
            v68,
            v71,
            v73,
            v75,
            v78,
            v80,
            v85,
            v86,
            v96,
            v97,
            v101,
            v104,
            v106,
            v112,
            v117,
            v119,
            v120,
            v128,
            v129,
            v131,
            v133,
            v138,
            v139,
            v140,
            v145,
            v148,
            v150,
            v151,
            v152,
            v156,
            v157,
            v178,
            v267,
            v348,
        )
    };
    let (
        v160,
        v162,
        v163,
        v169,
        v176,
        v195,
        v206,
        v208,
        v220,
        v224,
        v231,
        v238,
        v240,
        v244,
        v246,
        v250,
        v255,
        v257,
        v258,
        v260,
        v265,
        v268,
        v270,
        v271,
        v276,
        v278,
        v283,
        v287,
        v292,
        v296,
        v297,
        v299,
        v301,
        v302,
        v307,
        v313,
        v315,
    ) = {
        let v158: f64 = v152 - v157;
        let v159: f64 = v140 * v158;
        let v160: f64 = 0.384_f64;
        let v161: f64 = params[43];
        let v162: f64 = v50 * v145;
        let v163: f64 = v14 * v148;
        let v164: f64 = v162 + v163;
        let v165: f64 = v161 + v164;
        let v166: f64 = v160 * v165;
        let v167: f64 = v159 + v166;
        let v168: f64 = v34 * v167;
        let v169: f64 = v139 + v168;
        let v170: f64 = v133 + v169;
        let v171: f64 = 0.006806250000000001_f64;
        let v172: f64 = v171 * v138;
        let v173: f64 = v170 - v172;
        let v174: f64 = v173 - v159;
        let v175: f64 = v174 - v159;
        let v176: f64 = v9 + v175;
        let v177: f64 = v8 * v176;
        let v179: f64 = params[35];
        let v180: f64 = params[46];
        let v181: f64 = v50 * v48;
        let v182: f64 = v14 * v60;
        let v183: f64 = v181 + v182;
        let v184: f64 = v183 * v14;
        let v185: f64 = v50 * v68;
        let v186: f64 = v14 * v73;
        let v187: f64 = v185 + v186;
        let v188: f64 = v187 * v50;
        let v189: f64 = v184 - v188;
        let v190: f64 = v180 + v189;
        let v191: f64 = v190 * v11;
        let v192: f64 = params[48];
        let v193: f64 = v50 * v112;
        let v194: f64 = v14 * v117;
        let v195: f64 = v193 + v194;
        let v196: f64 = v192 - v195;
        let v197: f64 = v196 * v80;
        let v198: f64 = v191 - v197;
        let v199: f64 = -0.03168_f64;
        let v200: f64 = v199 * v138;
        let v201: f64 = v198 - v200;
        let v202: f64 = v140 * v165;
        let v203: f64 = v201 - v202;
        let v204: f64 = v160 * v158;
        let v205: f64 = v203 - v204;
        let v206: f64 = v179 + v205;
        let v207: f64 = v178 * v206;
        let v208: f64 = v177 - v207;
        let v209: f64 = v208 * v8;
        let v210: f64 = v62 * v50;
        let v211: f64 = v75 * v14;
        let v212: f64 = v210 + v211;
        let v213: f64 = v180 + v212;
        let v214: f64 = v11 * v213;
        let v215: f64 = v101 * v50;
        let v216: f64 = v86 * v14;
        let v217: f64 = v215 + v216;
        let v218: f64 = v192 - v217;
        let v219: f64 = v80 * v218;
        let v220: f64 = v214 - v219;
        let v221: f64 = v220 - v200;
        let v222: f64 = v221 - v204;
        let v223: f64 = v222 - v202;
        let v224: f64 = v179 + v223;
        let v225: f64 = v8 * v224;
        let v226: f64 = params[37];
        let v227: f64 = params[49];
        let v228: f64 = v183 * v50;
        let v229: f64 = v187 * v14;
        let v230: f64 = v228 + v229;
        let v231: f64 = v227 + v230;
        let v232: f64 = v231 + v169;
        let v233: f64 = 0.147456_f64;
        let v234: f64 = v233 * v138;
        let v235: f64 = v232 - v234;
        let v236: f64 = v235 - v166;
        let v237: f64 = v236 - v166;
        let v238: f64 = v226 + v237;
        let v239: f64 = v178 * v238;
        let v240: f64 = v225 - v239;
        let v241: f64 = v240 * v178;
        let v242: f64 = v209 - v241;
        let v243: f64 = params[30];
        let v244: f64 = v243 + v138;
        let v245: f64 = v171 * v244;
        let v246: f64 = 0.0825_f64;
        let v247: f64 = params[31];
        let v248: f64 = v140 * v138;
        let v249: f64 = v158 + v248;
        let v250: f64 = v247 + v249;
        let v251: f64 = v8 * v250;
        let v252: f64 = params[32];
        let v253: f64 = v160 * v138;
        let v254: f64 = v165 + v253;
        let v255: f64 = v252 + v254;
        let v256: f64 = v178 * v255;
        let v257: f64 = v251 - v256;
        let v258: f64 = v246 * v257;
        let v259: f64 = v34 * v258;
        let v260: f64 = v245 + v259;
        let v261: f64 = v242 + v260;
        let v262: f64 = v261 - v245;
        let v263: f64 = v262 - v258;
        let v264: f64 = v263 - v258;
        let v265: f64 = v6 + v264;
        let v266: f64 = v5 * v265;
        let v268: f64 = params[25];
        let v269: f64 = params[38];
        let v270: f64 = v80 * v151;
        let v271: f64 = v11 * v156;
        let v272: f64 = v270 + v271;
        let v273: f64 = v160 * v272;
        let v274: f64 = v80 * v213;
        let v275: f64 = v11 * v218;
        let v276: f64 = v274 + v275;
        let v277: f64 = v273 - v276;
        let v278: f64 = v269 + v277;
        let v279: f64 = v278 * v178;
        let v280: f64 = params[36];
        let v281: f64 = v80 * v120;
        let v282: f64 = v11 * v129;
        let v283: f64 = v281 + v282;
        let v284: f64 = v283 * v80;
        let v285: f64 = v80 * v78;
        let v286: f64 = v11 * v104;
        let v287: f64 = v285 + v286;
        let v288: f64 = v287 * v11;
        let v289: f64 = v284 - v288;
        let v290: f64 = v140 * v272;
        let v291: f64 = v289 + v290;
        let v292: f64 = v280 + v291;
        let v293: f64 = v292 * v8;
        let v294: f64 = v279 - v293;
        let v295: f64 = params[33];
        let v296: f64 = v295 - v272;
        let v297: f64 = v246 * v296;
        let v298: f64 = v294 + v297;
        let v299: f64 = v268 + v298;
        let v300: f64 = v267 * v299;
        let v301: f64 = v266 - v300;
        let v302: f64 = v301 * v5;
        let v303: f64 = v106 * v80;
        let v304: f64 = v131 * v11;
        let v305: f64 = v303 + v304;
        let v306: f64 = v290 - v305;
        let v307: f64 = v280 + v306;
        let v308: f64 = v8 * v307;
        let v309: f64 = v190 * v80;
        let v310: f64 = v196 * v11;
        let v311: f64 = v309 + v310;
        let v312: f64 = v273 - v311;
        let v313: f64 = v269 + v312;
        let v314: f64 = v178 * v313;
        let v315: f64 = v308 - v314;
        (
            v160,
            v162,
            v163,
            v169,
            v176,
            v195,
            v206,
            v208,
            v220,
            v224,
            v231,
            v238,
            v240,
            v244,
            v246,
            v250,
            v255,
            v257,
            v258,
            v260,
            v265,
            v268,
            v270,
            v271,
            v276,
            v278,
            v283,
            v287,
            v292,
            v296,
            v297,
            v299,
            v301,
            v302,
            v307,
            v313,
            v315,
        )
    };
    let (
        v317,
        v325,
        v327,
        v336,
        v344,
        v353,
        v390,
        v395,
        v407,
        v417,
        v428,
        v429,
        v436,
        v439,
        v442,
        v445,
        v450,
        v451,
        v460,
        v461,
        v464,
        v466,
        v470,
        v471,
        v473,
    ) = {
        let v316: f64 = v297 - v315;
        let v317: f64 = v268 + v316;
        let v318: f64 = v5 * v317;
        let v319: f64 = params[27];
        let v320: f64 = params[39];
        let v321: f64 = v287 * v80;
        let v322: f64 = v283 * v11;
        let v323: f64 = v321 + v322;
        let v324: f64 = v323 + v169;
        let v325: f64 = v320 + v324;
        let v326: f64 = v325 + v260;
        let v327: f64 = v319 + v326;
        let v328: f64 = v267 * v327;
        let v329: f64 = v318 - v328;
        let v330: f64 = v329 * v267;
        let v331: f64 = v302 - v330;
        let v332: f64 = 0.099856_f64;
        let v333: f64 = params[20];
        let v334: f64 = v333 + v244;
        let v335: f64 = v332 * v334;
        let v336: f64 = -0.316_f64;
        let v337: f64 = params[23];
        let v338: f64 = v178 * v250;
        let v339: f64 = v8 * v255;
        let v340: f64 = v338 + v339;
        let v341: f64 = v337 + v340;
        let v342: f64 = v336 * v341;
        let v343: f64 = v34 * v342;
        let v344: f64 = v335 - v343;
        let v345: f64 = v331 + v344;
        let v346: f64 = v3 + v345;
        let v347: f64 = v2 * v346;
        let v349: f64 = params[15];
        let v350: f64 = params[28];
        let v351: f64 = v178 * v307;
        let v352: f64 = v8 * v313;
        let v353: f64 = v351 + v352;
        let v354: f64 = v350 - v353;
        let v355: f64 = v354 * v267;
        let v356: f64 = params[26];
        let v357: f64 = v178 * v176;
        let v358: f64 = v8 * v206;
        let v359: f64 = v357 + v358;
        let v360: f64 = v359 * v8;
        let v361: f64 = v178 * v224;
        let v362: f64 = v8 * v238;
        let v363: f64 = v361 + v362;
        let v364: f64 = v363 * v178;
        let v365: f64 = v360 - v364;
        let v366: f64 = v246 * v340;
        let v367: f64 = v365 - v366;
        let v368: f64 = v356 + v367;
        let v369: f64 = v368 * v5;
        let v370: f64 = v355 - v369;
        let v371: f64 = params[21];
        let v372: f64 = v246 * v244;
        let v373: f64 = v257 + v372;
        let v374: f64 = v371 + v373;
        let v375: f64 = v5 * v374;
        let v376: f64 = params[22];
        let v377: f64 = v376 - v296;
        let v378: f64 = v267 * v377;
        let v379: f64 = v375 - v378;
        let v380: f64 = v336 * v379;
        let v381: f64 = v370 - v380;
        let v382: f64 = v349 + v381;
        let v383: f64 = v348 * v382;
        let v384: f64 = v347 + v383;
        let v385: f64 = v384 * v2;
        let v386: f64 = v208 * v178;
        let v387: f64 = v240 * v8;
        let v388: f64 = v386 + v387;
        let v389: f64 = v388 - v366;
        let v390: f64 = v356 + v389;
        let v391: f64 = v5 * v390;
        let v392: f64 = v292 * v178;
        let v393: f64 = v278 * v8;
        let v394: f64 = v392 + v393;
        let v395: f64 = v350 - v394;
        let v396: f64 = v267 * v395;
        let v397: f64 = v391 - v396;
        let v398: f64 = v397 + v380;
        let v399: f64 = v349 - v398;
        let v400: f64 = v2 * v399;
        let v401: f64 = params[17];
        let v402: f64 = params[29];
        let v403: f64 = v359 * v178;
        let v404: f64 = v363 * v8;
        let v405: f64 = v403 + v404;
        let v406: f64 = v405 + v260;
        let v407: f64 = v402 + v406;
        let v408: f64 = v407 + v344;
        let v409: f64 = v408 - v335;
        let v410: f64 = v409 + v342;
        let v411: f64 = v410 + v342;
        let v412: f64 = v401 + v411;
        let v413: f64 = v348 * v412;
        let v414: f64 = v400 + v413;
        let v415: f64 = v414 * v348;
        let v416: f64 = v385 + v415;
        let v417: f64 = v0 + v416;
        let v418: f64 = params[16];
        let v419: f64 = v301 * v267;
        let v420: f64 = v329 * v5;
        let v421: f64 = v419 + v420;
        let v422: f64 = v418 + v421;
        let v423: f64 = v2 * v422;
        let v424: f64 = params[18];
        let v425: f64 = v368 * v267;
        let v426: f64 = v354 * v5;
        let v427: f64 = v425 + v426;
        let v428: f64 = v267 * v374;
        let v429: f64 = v5 * v377;
        let v430: f64 = v428 + v429;
        let v431: f64 = v336 * v430;
        let v432: f64 = v427 + v431;
        let v433: f64 = v424 - v432;
        let v434: f64 = v348 * v433;
        let v435: f64 = v423 + v434;
        let v436: f64 = -v435;
        let v437: f64 = v348 * v407;
        let v438: f64 = v2 * v398;
        let v439: f64 = v437 - v438;
        let v440: f64 = v348 * v353;
        let v441: f64 = v5 * v315;
        let v442: f64 = v325 + v258;
        let v443: f64 = v267 * v442;
        let v444: f64 = v441 + v443;
        let v445: f64 = v339 + v338;
        let v446: f64 = v267 * v445;
        let v447: f64 = v336 * v446;
        let v448: f64 = v444 - v447;
        let v449: f64 = v2 * v448;
        let v450: f64 = v440 - v449;
        let v451: f64 = v157 - v152;
        let v452: f64 = v160 * v451;
        let v453: f64 = v220 + v452;
        let v454: f64 = v178 * v453;
        let v455: f64 = v140 * v451;
        let v456: f64 = v231 - v455;
        let v457: f64 = v8 * v456;
        let v458: f64 = v454 + v457;
        let v459: f64 = v246 * v451;
        let v460: f64 = v458 - v459;
        let v461: f64 = v348 * v460;
        let v462: f64 = v8 * v453;
        let v463: f64 = v178 * v456;
        let v464: f64 = v462 - v463;
        let v465: f64 = v5 * v464;
        let v466: f64 = v271 + v270;
        let v467: f64 = v178 * v466;
        let v468: f64 = v246 * v467;
        let v469: f64 = v160 * v466;
        let v470: f64 = v469 - v276;
        let v471: f64 = v468 - v470;
        let v472: f64 = v267 * v471;
        let v473: f64 = v465 - v472;
        (
            v317,
            v325,
            v327,
            v336,
            v344,
            v353,
            v390,
            v395,
            v407,
            v417,
            v428,
            v429,
            v436,
            v439,
            v442,
            v445,
            v450,
            v451,
            v460,
            v461,
            v464,
            v466,
            v470,
            v471,
            v473,
        )
    };
    let (
        v481,
        v495,
        v508,
        v525,
        v543,
        v549,
        v565,
        v582,
        v594,
        v600,
        v606,
        v614,
        v622,
        v630,
    ) = {
        let v474: f64 = v8 * v466;
        let v475: f64 = v267 * v474;
        let v476: f64 = v5 * v451;
        let v477: f64 = v475 + v476;
        let v478: f64 = v336 * v477;
        let v479: f64 = v473 - v478;
        let v480: f64 = v2 * v479;
        let v481: f64 = v461 - v480;
        let v482: f64 = v11 * v119;
        let v483: f64 = v80 * v128;
        let v484: f64 = v482 + v483;
        let v485: f64 = v163 + v162;
        let v486: f64 = v80 * v485;
        let v487: f64 = v160 * v486;
        let v488: f64 = v484 + v487;
        let v489: f64 = v178 * v488;
        let v490: f64 = v140 * v486;
        let v491: f64 = v195 - v490;
        let v492: f64 = v8 * v491;
        let v493: f64 = v489 + v492;
        let v494: f64 = v246 * v486;
        let v495: f64 = v493 - v494;
        let v496: f64 = v348 * v495;
        let v497: f64 = v8 * v488;
        let v498: f64 = v178 * v491;
        let v499: f64 = v497 - v498;
        let v500: f64 = v5 * v499;
        let v501: f64 = v11 * v128;
        let v502: f64 = v80 * v119;
        let v503: f64 = v501 - v502;
        let v504: f64 = v140 * v150;
        let v505: f64 = v11 * v485;
        let v506: f64 = v160 * v505;
        let v507: f64 = v504 + v506;
        let v508: f64 = v503 + v507;
        let v509: f64 = v8 * v150;
        let v510: f64 = v178 * v505;
        let v511: f64 = v509 - v510;
        let v512: f64 = v246 * v511;
        let v513: f64 = v508 + v512;
        let v514: f64 = v267 * v513;
        let v515: f64 = v500 + v514;
        let v516: f64 = v8 * v505;
        let v517: f64 = v178 * v150;
        let v518: f64 = v516 + v517;
        let v519: f64 = v267 * v518;
        let v520: f64 = v5 * v486;
        let v521: f64 = v519 + v520;
        let v522: f64 = v336 * v521;
        let v523: f64 = v515 - v522;
        let v524: f64 = v2 * v523;
        let v525: f64 = v496 - v524;
        let v526: f64 = v14 * v66;
        let v527: f64 = v71 + v41;
        let v528: f64 = v50 * v527;
        let v529: f64 = v526 + v528;
        let v530: f64 = v11 * v529;
        let v531: f64 = v80 * v85;
        let v532: f64 = v530 + v531;
        let v533: f64 = v97 + v96;
        let v534: f64 = v14 * v533;
        let v535: f64 = v80 * v534;
        let v536: f64 = v11 * v40;
        let v537: f64 = v535 + v536;
        let v538: f64 = v160 * v537;
        let v539: f64 = v532 + v538;
        let v540: f64 = v178 * v539;
        let v541: f64 = v50 * v66;
        let v542: f64 = v14 * v527;
        let v543: f64 = v541 - v542;
        let v544: f64 = v140 * v537;
        let v545: f64 = v543 - v544;
        let v546: f64 = v8 * v545;
        let v547: f64 = v540 + v546;
        let v548: f64 = v246 * v537;
        let v549: f64 = v547 - v548;
        let v550: f64 = v348 * v549;
        let v551: f64 = v8 * v539;
        let v552: f64 = v178 * v545;
        let v553: f64 = v551 - v552;
        let v554: f64 = v5 * v553;
        let v555: f64 = v11 * v85;
        let v556: f64 = v80 * v529;
        let v557: f64 = v555 - v556;
        let v558: f64 = v50 * v533;
        let v559: f64 = v140 * v558;
        let v560: f64 = v80 * v40;
        let v561: f64 = v11 * v534;
        let v562: f64 = v560 - v561;
        let v563: f64 = v160 * v562;
        let v564: f64 = v559 + v563;
        let v565: f64 = v557 - v564;
        let v566: f64 = v178 * v562;
        let v567: f64 = v8 * v558;
        let v568: f64 = v566 - v567;
        let v569: f64 = v246 * v568;
        let v570: f64 = v565 + v569;
        let v571: f64 = v267 * v570;
        let v572: f64 = v554 + v571;
        let v573: f64 = v8 * v562;
        let v574: f64 = v178 * v558;
        let v575: f64 = v573 + v574;
        let v576: f64 = v267 * v575;
        let v577: f64 = v5 * v537;
        let v578: f64 = v576 - v577;
        let v579: f64 = v336 * v578;
        let v580: f64 = v572 + v579;
        let v581: f64 = v2 * v580;
        let v582: f64 = v550 - v581;
        let v583: f64 = params[19];
        let v584: f64 = v267 * v265;
        let v585: f64 = v5 * v299;
        let v586: f64 = v584 + v585;
        let v587: f64 = v586 * v267;
        let v588: f64 = v267 * v317;
        let v589: f64 = v5 * v327;
        let v590: f64 = v588 + v589;
        let v591: f64 = v590 * v5;
        let v592: f64 = v587 + v591;
        let v593: f64 = v592 + v344;
        let v594: f64 = v583 + v593;
        let v595: f64 = v267 * v390;
        let v596: f64 = v5 * v395;
        let v597: f64 = v595 + v596;
        let v598: f64 = v429 + v428;
        let v599: f64 = v336 * v598;
        let v600: f64 = v597 + v599;
        let v601: f64 = v267 * v315;
        let v602: f64 = v5 * v442;
        let v603: f64 = v601 - v602;
        let v604: f64 = v5 * v445;
        let v605: f64 = v336 * v604;
        let v606: f64 = v603 + v605;
        let v607: f64 = v267 * v464;
        let v608: f64 = v5 * v471;
        let v609: f64 = v607 + v608;
        let v610: f64 = v267 * v451;
        let v611: f64 = v5 * v474;
        let v612: f64 = v610 - v611;
        let v613: f64 = v336 * v612;
        let v614: f64 = v609 - v613;
        let v615: f64 = v267 * v499;
        let v616: f64 = v5 * v513;
        let v617: f64 = v615 - v616;
        let v618: f64 = v267 * v486;
        let v619: f64 = v5 * v518;
        let v620: f64 = v618 - v619;
        let v621: f64 = v336 * v620;
        let v622: f64 = v617 - v621;
        let v623: f64 = v267 * v553;
        let v624: f64 = v5 * v570;
        let v625: f64 = v623 - v624;
        let v626: f64 = v5 * v575;
        let v627: f64 = v267 * v537;
        let v628: f64 = v626 + v627;
        let v629: f64 = v336 * v628;
        let v630: f64 = v625 - v629;
        (
            v481,
            v495,
            v508,
            v525,
            v543,
            v549,
            v565,
            v582,
            v594,
            v600,
            v606,
            v614,
            v622,
            v630,
        )
    };
    [
        [v417, v436, v439, v450, v481, v525, v582],
        [v436, v594, v600, v606, v614, v622, v630],
        [v439, v600, v407, v353, v460, v495, v549],
        [v450, v606, v353, v325, v470, v508, v565],
        [v481, v614, v460, v470, v231, v195, v543],
        [v525, v622, v495, v508, v195, v128, v85],
        [v582, v630, v549, v565, v543, v85, v71],
    ]
}
/// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
///
/// # Inputs
///
/// - `q: &[f64; 7]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 7]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 70]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis_matrix: [[f64; 7]; 7]` (7 x 7, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
///
/// Operation count: 7600 floating-point operations, 12 trig calls.
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
    q: &[f64; 7],
    qd: &[f64; 7],
    params: &[f64; 70],
) -> [[f64; 7]; 7] {
    let (
        v0,
        v2,
        v3,
        v4,
        v6,
        v7,
        v9,
        v10,
        v13,
        v14,
        v17,
        v18,
        v19,
        v21,
        v23,
        v24,
        v25,
        v28,
        v30,
        v33,
        v36,
        v39,
        v40,
        v42,
        v44,
        v45,
        v47,
        v49,
        v52,
        v54,
        v55,
        v57,
        v59,
        v61,
        v64,
        v67,
        v70,
        v73,
        v75,
        v77,
        v80,
        v82,
        v84,
        v86,
        v89,
        v91,
        v92,
        v94,
        v96,
        v98,
        v101,
        v104,
        v107,
        v109,
        v115,
        v117,
        v122,
        v123,
        v125,
        v127,
        v129,
        v132,
        v135,
        v138,
        v139,
        v141,
        v143,
        v145,
        v149,
        v151,
        v154,
        v157,
        v160,
        v165,
        v167,
        v170,
        v173,
        v174,
        v176,
        v179,
        v183,
        v190,
        v197,
    ) = {
        let v0: f64 = 0.5_f64;
        let v1: f64 = q[2];
        let (v4, v2): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = params[25];
        let v5: f64 = q[1];
        let (v6, v14): (f64, f64) = ::armdyn_runtime::libm::sincos(v5);
        let v7: f64 = v4 * v6;
        let v8: f64 = v3 * v7;
        let v9: f64 = params[24];
        let v10: f64 = v2 * v6;
        let v11: f64 = v9 * v10;
        let v12: f64 = v8 - v11;
        let v13: f64 = params[26];
        let v15: f64 = v13 * v14;
        let v16: f64 = v12 + v15;
        let v17: f64 = params[23];
        let v18: f64 = 0.316_f64;
        let v19: f64 = v18 * v10;
        let v20: f64 = v17 * v19;
        let v21: f64 = v16 - v20;
        let v22: f64 = q[3];
        let (v25, v23): (f64, f64) = ::armdyn_runtime::libm::sincos(v22);
        let v24: f64 = params[34];
        let v26: f64 = v25 * v14;
        let v27: f64 = v23 * v10;
        let v28: f64 = v26 - v27;
        let v29: f64 = v24 * v28;
        let v30: f64 = params[35];
        let v31: f64 = v23 * v14;
        let v32: f64 = v25 * v10;
        let v33: f64 = v31 + v32;
        let v34: f64 = v30 * v33;
        let v35: f64 = v29 + v34;
        let v36: f64 = params[36];
        let v37: f64 = v36 * v7;
        let v38: f64 = v35 - v37;
        let v39: f64 = params[32];
        let v40: f64 = 0.0825_f64;
        let v41: f64 = v40 * v14;
        let v42: f64 = v19 + v41;
        let v43: f64 = v39 * v42;
        let v44: f64 = params[33];
        let v45: f64 = v40 * v7;
        let v46: f64 = v23 * v45;
        let v47: f64 = v18 * v7;
        let v48: f64 = v25 * v47;
        let v49: f64 = v46 + v48;
        let v50: f64 = v44 * v49;
        let v51: f64 = v43 - v50;
        let v52: f64 = v38 - v51;
        let v53: f64 = q[4];
        let (v57, v54): (f64, f64) = ::armdyn_runtime::libm::sincos(v53);
        let v55: f64 = params[44];
        let v56: f64 = v54 * v28;
        let v58: f64 = v57 * v7;
        let v59: f64 = v56 + v58;
        let v60: f64 = v55 * v59;
        let v61: f64 = params[45];
        let v62: f64 = v57 * v28;
        let v63: f64 = v54 * v7;
        let v64: f64 = v62 - v63;
        let v65: f64 = v61 * v64;
        let v66: f64 = v60 - v65;
        let v67: f64 = params[46];
        let v68: f64 = v67 * v33;
        let v69: f64 = v66 + v68;
        let v70: f64 = params[43];
        let v71: f64 = v23 * v47;
        let v72: f64 = v25 * v45;
        let v73: f64 = v71 - v72;
        let v74: f64 = v57 * v73;
        let v75: f64 = -0.0825_f64;
        let v76: f64 = v75 * v33;
        let v77: f64 = v76 + v42;
        let v78: f64 = v54 * v77;
        let v79: f64 = v74 - v78;
        let v80: f64 = 0.384_f64;
        let v81: f64 = v80 * v59;
        let v82: f64 = v79 + v81;
        let v83: f64 = v70 * v82;
        let v84: f64 = params[42];
        let v85: f64 = v75 * v7;
        let v86: f64 = v49 + v85;
        let v87: f64 = v84 * v86;
        let v88: f64 = v83 - v87;
        let v89: f64 = v69 + v88;
        let v90: f64 = q[5];
        let (v94, v91): (f64, f64) = ::armdyn_runtime::libm::sincos(v90);
        let v92: f64 = params[54];
        let v93: f64 = v91 * v59;
        let v95: f64 = v94 * v33;
        let v96: f64 = v93 + v95;
        let v97: f64 = v92 * v96;
        let v98: f64 = params[55];
        let v99: f64 = v91 * v33;
        let v100: f64 = v94 * v59;
        let v101: f64 = v99 - v100;
        let v102: f64 = v98 * v101;
        let v103: f64 = v97 + v102;
        let v104: f64 = params[56];
        let v105: f64 = v104 * v64;
        let v106: f64 = v103 + v105;
        let v107: f64 = params[52];
        let v108: f64 = v107 * v82;
        let v109: f64 = params[53];
        let v110: f64 = v91 * v86;
        let v111: f64 = v54 * v73;
        let v112: f64 = v57 * v77;
        let v113: f64 = v111 + v112;
        let v114: f64 = v80 * v64;
        let v115: f64 = v113 - v114;
        let v116: f64 = v94 * v115;
        let v117: f64 = v110 + v116;
        let v118: f64 = v109 * v117;
        let v119: f64 = v108 + v118;
        let v120: f64 = v106 + v119;
        let v121: f64 = q[6];
        let (v125, v122): (f64, f64) = ::armdyn_runtime::libm::sincos(v121);
        let v123: f64 = params[64];
        let v124: f64 = v122 * v96;
        let v126: f64 = v125 * v64;
        let v127: f64 = v124 + v126;
        let v128: f64 = v123 * v127;
        let v129: f64 = params[65];
        let v130: f64 = v122 * v64;
        let v131: f64 = v125 * v96;
        let v132: f64 = v130 - v131;
        let v133: f64 = v129 * v132;
        let v134: f64 = v128 + v133;
        let v135: f64 = params[66];
        let v136: f64 = v135 * v101;
        let v137: f64 = v134 - v136;
        let v138: f64 = params[62];
        let v139: f64 = 0.088_f64;
        let v140: f64 = v139 * v64;
        let v141: f64 = v140 - v117;
        let v142: f64 = v138 * v141;
        let v143: f64 = params[63];
        let v144: f64 = v139 * v101;
        let v145: f64 = v82 - v144;
        let v146: f64 = v122 * v145;
        let v147: f64 = v91 * v115;
        let v148: f64 = v94 * v86;
        let v149: f64 = v147 - v148;
        let v150: f64 = v125 * v149;
        let v151: f64 = v146 - v150;
        let v152: f64 = v143 * v151;
        let v153: f64 = v142 + v152;
        let v154: f64 = v137 - v153;
        let v155: f64 = v122 * v154;
        let v156: f64 = v129 * v127;
        let v157: f64 = params[67];
        let v158: f64 = v157 * v132;
        let v159: f64 = v156 + v158;
        let v160: f64 = params[68];
        let v161: f64 = v160 * v101;
        let v162: f64 = v159 - v161;
        let v163: f64 = v122 * v149;
        let v164: f64 = v125 * v145;
        let v165: f64 = v163 + v164;
        let v166: f64 = v143 * v165;
        let v167: f64 = params[61];
        let v168: f64 = v167 * v141;
        let v169: f64 = v166 + v168;
        let v170: f64 = v162 + v169;
        let v171: f64 = v125 * v170;
        let v172: f64 = v155 - v171;
        let v173: f64 = v120 + v172;
        let v174: f64 = v91 * v173;
        let v175: f64 = v98 * v96;
        let v176: f64 = params[57];
        let v177: f64 = v176 * v101;
        let v178: f64 = v175 + v177;
        let v179: f64 = params[58];
        let v180: f64 = v179 * v64;
        let v181: f64 = v178 + v180;
        let v182: f64 = v109 * v149;
        let v183: f64 = params[51];
        let v184: f64 = v183 * v82;
        let v185: f64 = v182 - v184;
        let v186: f64 = v181 + v185;
        let v187: f64 = v135 * v127;
        let v188: f64 = v160 * v132;
        let v189: f64 = v187 + v188;
        let v190: f64 = params[69];
        let v191: f64 = v190 * v101;
        let v192: f64 = v189 - v191;
        let v193: f64 = v167 * v151;
        let v194: f64 = v138 * v165;
        let v195: f64 = v193 - v194;
        let v196: f64 = v192 + v195;
        let v197: f64 = v186 - v196;
        (
            v0,
            v2,
            v3,
            v4,
            v6,
            v7,
            v9,
            v10,
            v13,
            v14,
            v17,
            v18,
            v19,
            v21,
            v23,
            v24,
            v25,
            v28,
            v30,
            v33,
            v36,
            v39,
            v40,
            v42,
            v44,
            v45,
            v47,
            v49,
            v52,
            v54,
            v55,
            v57,
            v59,
            v61,
            v64,
            v67,
            v70,
            v73,
            v75,
            v77,
            v80,
            v82,
            v84,
            v86,
            v89,
            v91,
            v92,
            v94,
            v96,
            v98,
            v101,
            v104,
            v107,
            v109,
            v115,
            v117,
            v122,
            v123,
            v125,
            v127,
            v129,
            v132,
            v135,
            v138,
            v139,
            v141,
            v143,
            v145,
            v149,
            v151,
            v154,
            v157,
            v160,
            v165,
            v167,
            v170,
            v173,
            v174,
            v176,
            v179,
            v183,
            v190,
            v197,
        )
    };
    let (
        v198,
        v203,
        v209,
        v213,
        v217,
        v221,
        v224,
        v231,
        v233,
        v236,
        v239,
        v249,
        v281,
        v288,
        v291,
        v293,
        v296,
        v299,
        v302,
        v306,
        v313,
        v329,
        v333,
        v335,
        v343,
        v346,
        v349,
        v350,
        v351,
        v355,
        v363,
        v382,
        v385,
        v394,
        v395,
    ) = {
        let v198: f64 = params[60];
        let v199: f64 = v198 * v165;
        let v200: f64 = v143 * v132;
        let v201: f64 = v138 * v101;
        let v202: f64 = v200 + v201;
        let v203: f64 = v199 + v202;
        let v204: f64 = v125 * v203;
        let v205: f64 = v198 * v151;
        let v206: f64 = v167 * v101;
        let v207: f64 = v143 * v127;
        let v208: f64 = v206 + v207;
        let v209: f64 = v205 - v208;
        let v210: f64 = v122 * v209;
        let v211: f64 = v204 + v210;
        let v212: f64 = v139 * v211;
        let v213: f64 = v197 - v212;
        let v214: f64 = v94 * v213;
        let v215: f64 = v174 - v214;
        let v216: f64 = v89 + v215;
        let v217: f64 = params[41];
        let v218: f64 = v217 * v33;
        let v219: f64 = v70 * v59;
        let v220: f64 = v218 - v219;
        let v221: f64 = params[40];
        let v222: f64 = v221 * v82;
        let v223: f64 = v220 - v222;
        let v224: f64 = params[50];
        let v225: f64 = v224 * v82;
        let v226: f64 = v107 * v96;
        let v227: f64 = v183 * v101;
        let v228: f64 = v226 - v227;
        let v229: f64 = v225 + v228;
        let v230: f64 = v229 + v211;
        let v231: f64 = v223 - v230;
        let v232: f64 = v80 * v231;
        let v233: f64 = v216 - v232;
        let v234: f64 = v54 * v233;
        let v235: f64 = v61 * v59;
        let v236: f64 = params[47];
        let v237: f64 = v236 * v64;
        let v238: f64 = v235 - v237;
        let v239: f64 = params[48];
        let v240: f64 = v239 * v33;
        let v241: f64 = v238 + v240;
        let v242: f64 = v70 * v115;
        let v243: f64 = v217 * v86;
        let v244: f64 = v242 + v243;
        let v245: f64 = v241 + v244;
        let v246: f64 = v104 * v96;
        let v247: f64 = v179 * v101;
        let v248: f64 = v246 + v247;
        let v249: f64 = params[59];
        let v250: f64 = v249 * v64;
        let v251: f64 = v248 + v250;
        let v252: f64 = v183 * v117;
        let v253: f64 = v107 * v149;
        let v254: f64 = v252 + v253;
        let v255: f64 = v251 - v254;
        let v256: f64 = v125 * v154;
        let v257: f64 = v122 * v170;
        let v258: f64 = v256 + v257;
        let v259: f64 = v255 + v258;
        let v260: f64 = v138 * v127;
        let v261: f64 = v167 * v132;
        let v262: f64 = v260 - v261;
        let v263: f64 = v198 * v141;
        let v264: f64 = v262 - v263;
        let v265: f64 = v139 * v264;
        let v266: f64 = v259 - v265;
        let v267: f64 = v245 - v266;
        let v268: f64 = v221 * v115;
        let v269: f64 = v70 * v64;
        let v270: f64 = v84 * v33;
        let v271: f64 = v269 + v270;
        let v272: f64 = v268 - v271;
        let v273: f64 = v224 * v149;
        let v274: f64 = v109 * v101;
        let v275: f64 = v107 * v64;
        let v276: f64 = v274 - v275;
        let v277: f64 = v273 + v276;
        let v278: f64 = v122 * v203;
        let v279: f64 = v125 * v209;
        let v280: f64 = v278 - v279;
        let v281: f64 = v277 + v280;
        let v282: f64 = v91 * v281;
        let v283: f64 = v183 * v64;
        let v284: f64 = v109 * v96;
        let v285: f64 = v283 - v284;
        let v286: f64 = v224 * v117;
        let v287: f64 = v285 - v286;
        let v288: f64 = v287 - v264;
        let v289: f64 = v94 * v288;
        let v290: f64 = v282 - v289;
        let v291: f64 = v272 + v290;
        let v292: f64 = v80 * v291;
        let v293: f64 = v267 + v292;
        let v294: f64 = v57 * v293;
        let v295: f64 = v234 - v294;
        let v296: f64 = v52 + v295;
        let v297: f64 = v23 * v296;
        let v298: f64 = v30 * v28;
        let v299: f64 = params[37];
        let v300: f64 = v299 * v33;
        let v301: f64 = v298 + v300;
        let v302: f64 = params[38];
        let v303: f64 = v302 * v7;
        let v304: f64 = v301 - v303;
        let v305: f64 = v44 * v73;
        let v306: f64 = params[31];
        let v307: f64 = v306 * v42;
        let v308: f64 = v305 + v307;
        let v309: f64 = v304 + v308;
        let v310: f64 = v67 * v59;
        let v311: f64 = v239 * v64;
        let v312: f64 = v310 - v311;
        let v313: f64 = params[49];
        let v314: f64 = v313 * v33;
        let v315: f64 = v312 + v314;
        let v316: f64 = v217 * v82;
        let v317: f64 = v84 * v115;
        let v318: f64 = v316 + v317;
        let v319: f64 = v315 - v318;
        let v320: f64 = v94 * v173;
        let v321: f64 = v91 * v213;
        let v322: f64 = v320 + v321;
        let v323: f64 = v319 + v322;
        let v324: f64 = v309 + v323;
        let v325: f64 = v57 * v291;
        let v326: f64 = v54 * v231;
        let v327: f64 = v325 + v326;
        let v328: f64 = v75 * v327;
        let v329: f64 = v324 + v328;
        let v330: f64 = v25 * v329;
        let v331: f64 = v297 - v330;
        let v332: f64 = v21 + v331;
        let v333: f64 = params[20];
        let v334: f64 = v333 * v19;
        let v335: f64 = params[21];
        let v336: f64 = v335 * v14;
        let v337: f64 = v17 * v10;
        let v338: f64 = v336 + v337;
        let v339: f64 = v334 + v338;
        let v340: f64 = v39 * v28;
        let v341: f64 = v306 * v33;
        let v342: f64 = v340 - v341;
        let v343: f64 = params[30];
        let v344: f64 = v343 * v42;
        let v345: f64 = v342 - v344;
        let v346: f64 = v345 - v327;
        let v347: f64 = v339 - v346;
        let v348: f64 = v18 * v347;
        let v349: f64 = v332 - v348;
        let v350: f64 = v2 * v349;
        let v351: f64 = params[27];
        let v352: f64 = v351 * v7;
        let v353: f64 = v3 * v10;
        let v354: f64 = v352 - v353;
        let v355: f64 = params[28];
        let v356: f64 = v355 * v14;
        let v357: f64 = v354 + v356;
        let v358: f64 = v17 * v47;
        let v359: f64 = v357 + v358;
        let v360: f64 = v36 * v28;
        let v361: f64 = v302 * v33;
        let v362: f64 = v360 + v361;
        let v363: f64 = params[39];
        let v364: f64 = v363 * v7;
        let v365: f64 = v362 - v364;
        let v366: f64 = v306 * v49;
        let v367: f64 = v39 * v73;
        let v368: f64 = v366 + v367;
        let v369: f64 = v365 - v368;
        let v370: f64 = v57 * v233;
        let v371: f64 = v54 * v293;
        let v372: f64 = v370 + v371;
        let v373: f64 = v369 - v372;
        let v374: f64 = v84 * v59;
        let v375: f64 = v217 * v64;
        let v376: f64 = v374 + v375;
        let v377: f64 = v221 * v86;
        let v378: f64 = v376 - v377;
        let v379: f64 = v94 * v281;
        let v380: f64 = v91 * v288;
        let v381: f64 = v379 + v380;
        let v382: f64 = v378 + v381;
        let v383: f64 = v75 * v382;
        let v384: f64 = v373 + v383;
        let v385: f64 = v359 - v384;
        let v386: f64 = v343 * v73;
        let v387: f64 = v44 * v33;
        let v388: f64 = v39 * v7;
        let v389: f64 = v387 + v388;
        let v390: f64 = v386 + v389;
        let v391: f64 = v54 * v291;
        let v392: f64 = v57 * v231;
        let v393: f64 = v391 - v392;
        let v394: f64 = v390 + v393;
        let v395: f64 = v25 * v394;
        (
            v198,
            v203,
            v209,
            v213,
            v217,
            v221,
            v224,
            v231,
            v233,
            v236,
            v239,
            v249,
            v281,
            v288,
            v291,
            v293,
            v296,
            v299,
            v302,
            v306,
            v313,
            v329,
            v333,
            v335,
            v343,
            v346,
            v349,
            v350,
            v351,
            v355,
            v363,
            v382,
            v385,
            v394,
            v395,
        )
    };
    let (
        v401,
        v408,
        v417,
        v420,
        v421,
        v422,
        v426,
        v427,
        v429,
        v434,
        v436,
        v439,
        v443,
        v449,
        v453,
        v455,
        v458,
        v461,
        v465,
        v472,
        v479,
        v482,
        v488,
        v492,
        v503,
        v505,
        v511,
        v515,
        v525,
        v530,
        v533,
        v546,
        v549,
        v568,
        v574,
        v580,
        v582,
        v584,
        v587,
        v592,
        v593,
    ) = {
        let v396: f64 = v343 * v49;
        let v397: f64 = v306 * v7;
        let v398: f64 = v44 * v28;
        let v399: f64 = v397 + v398;
        let v400: f64 = v396 + v399;
        let v401: f64 = v382 - v400;
        let v402: f64 = v23 * v401;
        let v403: f64 = v395 + v402;
        let v404: f64 = v40 * v403;
        let v405: f64 = v385 - v404;
        let v406: f64 = v333 * v47;
        let v407: f64 = v17 * v7;
        let v408: f64 = params[22];
        let v409: f64 = v408 * v14;
        let v410: f64 = v407 - v409;
        let v411: f64 = v406 + v410;
        let v412: f64 = v23 * v394;
        let v413: f64 = v25 * v401;
        let v414: f64 = v412 - v413;
        let v415: f64 = v411 + v414;
        let v416: f64 = v18 * v415;
        let v417: f64 = v405 + v416;
        let v418: f64 = v4 * v417;
        let v419: f64 = v350 - v418;
        let v420: f64 = params[15];
        let v421: f64 = v420 * v14;
        let v422: f64 = params[14];
        let v423: f64 = v422 * v6;
        let v424: f64 = v421 + v423;
        let v425: f64 = v419 - v424;
        let v426: f64 = v425 * v14;
        let v427: f64 = v4 * v14;
        let v428: f64 = v3 * v427;
        let v429: f64 = v2 * v14;
        let v430: f64 = v9 * v429;
        let v431: f64 = v428 - v430;
        let v432: f64 = v13 * v6;
        let v433: f64 = v431 - v432;
        let v434: f64 = v18 * v429;
        let v435: f64 = v17 * v434;
        let v436: f64 = v433 - v435;
        let v437: f64 = v25 * v429;
        let v438: f64 = v23 * v6;
        let v439: f64 = v437 - v438;
        let v440: f64 = v30 * v439;
        let v441: f64 = v25 * v6;
        let v442: f64 = v23 * v429;
        let v443: f64 = v441 + v442;
        let v444: f64 = v24 * v443;
        let v445: f64 = v440 - v444;
        let v446: f64 = v36 * v427;
        let v447: f64 = v445 - v446;
        let v448: f64 = v40 * v6;
        let v449: f64 = v434 - v448;
        let v450: f64 = v39 * v449;
        let v451: f64 = v40 * v427;
        let v452: f64 = v23 * v451;
        let v453: f64 = v18 * v427;
        let v454: f64 = v25 * v453;
        let v455: f64 = v452 + v454;
        let v456: f64 = v44 * v455;
        let v457: f64 = v450 - v456;
        let v458: f64 = v447 - v457;
        let v459: f64 = v57 * v427;
        let v460: f64 = v54 * v443;
        let v461: f64 = v459 - v460;
        let v462: f64 = v55 * v461;
        let v463: f64 = v57 * v443;
        let v464: f64 = v54 * v427;
        let v465: f64 = v463 + v464;
        let v466: f64 = v61 * v465;
        let v467: f64 = v462 + v466;
        let v468: f64 = v67 * v439;
        let v469: f64 = v467 + v468;
        let v470: f64 = v23 * v453;
        let v471: f64 = v25 * v451;
        let v472: f64 = v470 - v471;
        let v473: f64 = v57 * v472;
        let v474: f64 = v75 * v439;
        let v475: f64 = v474 + v449;
        let v476: f64 = v54 * v475;
        let v477: f64 = v473 - v476;
        let v478: f64 = v80 * v461;
        let v479: f64 = v477 + v478;
        let v480: f64 = v70 * v479;
        let v481: f64 = v75 * v427;
        let v482: f64 = v455 + v481;
        let v483: f64 = v84 * v482;
        let v484: f64 = v480 - v483;
        let v485: f64 = v469 + v484;
        let v486: f64 = v91 * v461;
        let v487: f64 = v94 * v439;
        let v488: f64 = v486 + v487;
        let v489: f64 = v92 * v488;
        let v490: f64 = v91 * v439;
        let v491: f64 = v94 * v461;
        let v492: f64 = v490 - v491;
        let v493: f64 = v98 * v492;
        let v494: f64 = v489 + v493;
        let v495: f64 = v104 * v465;
        let v496: f64 = v494 - v495;
        let v497: f64 = v107 * v479;
        let v498: f64 = v91 * v482;
        let v499: f64 = v54 * v472;
        let v500: f64 = v57 * v475;
        let v501: f64 = v499 + v500;
        let v502: f64 = v80 * v465;
        let v503: f64 = v501 + v502;
        let v504: f64 = v94 * v503;
        let v505: f64 = v498 + v504;
        let v506: f64 = v109 * v505;
        let v507: f64 = v497 + v506;
        let v508: f64 = v496 + v507;
        let v509: f64 = v122 * v488;
        let v510: f64 = v125 * v465;
        let v511: f64 = v509 - v510;
        let v512: f64 = v123 * v511;
        let v513: f64 = v122 * v465;
        let v514: f64 = v125 * v488;
        let v515: f64 = v513 + v514;
        let v516: f64 = v129 * v515;
        let v517: f64 = v512 - v516;
        let v518: f64 = v135 * v492;
        let v519: f64 = v517 - v518;
        let v520: f64 = v139 * v492;
        let v521: f64 = v479 - v520;
        let v522: f64 = v122 * v521;
        let v523: f64 = v91 * v503;
        let v524: f64 = v94 * v482;
        let v525: f64 = v523 - v524;
        let v526: f64 = v125 * v525;
        let v527: f64 = v522 - v526;
        let v528: f64 = v143 * v527;
        let v529: f64 = v139 * v465;
        let v530: f64 = v529 + v505;
        let v531: f64 = v138 * v530;
        let v532: f64 = v528 - v531;
        let v533: f64 = v519 - v532;
        let v534: f64 = v122 * v533;
        let v535: f64 = v129 * v511;
        let v536: f64 = v157 * v515;
        let v537: f64 = v535 - v536;
        let v538: f64 = v160 * v492;
        let v539: f64 = v537 - v538;
        let v540: f64 = v122 * v525;
        let v541: f64 = v125 * v521;
        let v542: f64 = v540 + v541;
        let v543: f64 = v143 * v542;
        let v544: f64 = v167 * v530;
        let v545: f64 = v543 - v544;
        let v546: f64 = v539 + v545;
        let v547: f64 = v125 * v546;
        let v548: f64 = v534 - v547;
        let v549: f64 = v508 + v548;
        let v550: f64 = v91 * v549;
        let v551: f64 = v98 * v488;
        let v552: f64 = v176 * v492;
        let v553: f64 = v551 + v552;
        let v554: f64 = v179 * v465;
        let v555: f64 = v553 - v554;
        let v556: f64 = v109 * v525;
        let v557: f64 = v183 * v479;
        let v558: f64 = v556 - v557;
        let v559: f64 = v555 + v558;
        let v560: f64 = v135 * v511;
        let v561: f64 = v160 * v515;
        let v562: f64 = v560 - v561;
        let v563: f64 = v190 * v492;
        let v564: f64 = v562 - v563;
        let v565: f64 = v167 * v527;
        let v566: f64 = v138 * v542;
        let v567: f64 = v565 - v566;
        let v568: f64 = v564 + v567;
        let v569: f64 = v559 - v568;
        let v570: f64 = v198 * v542;
        let v571: f64 = v138 * v492;
        let v572: f64 = v143 * v515;
        let v573: f64 = v571 - v572;
        let v574: f64 = v570 + v573;
        let v575: f64 = v125 * v574;
        let v576: f64 = v198 * v527;
        let v577: f64 = v167 * v492;
        let v578: f64 = v143 * v511;
        let v579: f64 = v577 + v578;
        let v580: f64 = v576 - v579;
        let v581: f64 = v122 * v580;
        let v582: f64 = v575 + v581;
        let v583: f64 = v139 * v582;
        let v584: f64 = v569 - v583;
        let v585: f64 = v94 * v584;
        let v586: f64 = v550 - v585;
        let v587: f64 = v485 + v586;
        let v588: f64 = v217 * v439;
        let v589: f64 = v70 * v461;
        let v590: f64 = v588 - v589;
        let v591: f64 = v221 * v479;
        let v592: f64 = v590 - v591;
        let v593: f64 = v224 * v479;
        (
            v401,
            v408,
            v417,
            v420,
            v421,
            v422,
            v426,
            v427,
            v429,
            v434,
            v436,
            v439,
            v443,
            v449,
            v453,
            v455,
            v458,
            v461,
            v465,
            v472,
            v479,
            v482,
            v488,
            v492,
            v503,
            v505,
            v511,
            v515,
            v525,
            v530,
            v533,
            v546,
            v549,
            v568,
            v574,
            v580,
            v582,
            v584,
            v587,
            v592,
            v593,
        )
    };
    let (
        v631,
        v661,
        v684,
        v690,
        v704,
        v707,
        v739,
        v771,
        v775,
        v779,
        v780,
        v782,
        v786,
        v788,
        v791,
    ) = {
        let v594: f64 = v107 * v488;
        let v595: f64 = v183 * v492;
        let v596: f64 = v594 - v595;
        let v597: f64 = v593 + v596;
        let v598: f64 = v597 + v582;
        let v599: f64 = v592 - v598;
        let v600: f64 = v80 * v599;
        let v601: f64 = v587 - v600;
        let v602: f64 = v54 * v601;
        let v603: f64 = v61 * v461;
        let v604: f64 = v236 * v465;
        let v605: f64 = v603 + v604;
        let v606: f64 = v239 * v439;
        let v607: f64 = v605 + v606;
        let v608: f64 = v70 * v503;
        let v609: f64 = v217 * v482;
        let v610: f64 = v608 + v609;
        let v611: f64 = v607 + v610;
        let v612: f64 = v104 * v488;
        let v613: f64 = v179 * v492;
        let v614: f64 = v612 + v613;
        let v615: f64 = v249 * v465;
        let v616: f64 = v614 - v615;
        let v617: f64 = v183 * v505;
        let v618: f64 = v107 * v525;
        let v619: f64 = v617 + v618;
        let v620: f64 = v616 - v619;
        let v621: f64 = v125 * v533;
        let v622: f64 = v122 * v546;
        let v623: f64 = v621 + v622;
        let v624: f64 = v620 + v623;
        let v625: f64 = v138 * v511;
        let v626: f64 = v167 * v515;
        let v627: f64 = v625 + v626;
        let v628: f64 = v198 * v530;
        let v629: f64 = v627 + v628;
        let v630: f64 = v139 * v629;
        let v631: f64 = v624 - v630;
        let v632: f64 = v611 - v631;
        let v633: f64 = v221 * v503;
        let v634: f64 = v84 * v439;
        let v635: f64 = v70 * v465;
        let v636: f64 = v634 - v635;
        let v637: f64 = v633 - v636;
        let v638: f64 = v224 * v525;
        let v639: f64 = v109 * v492;
        let v640: f64 = v107 * v465;
        let v641: f64 = v639 + v640;
        let v642: f64 = v638 + v641;
        let v643: f64 = v122 * v574;
        let v644: f64 = v125 * v580;
        let v645: f64 = v643 - v644;
        let v646: f64 = v642 + v645;
        let v647: f64 = v91 * v646;
        let v648: f64 = v183 * v465;
        let v649: f64 = v109 * v488;
        let v650: f64 = v648 + v649;
        let v651: f64 = v224 * v505;
        let v652: f64 = v650 + v651;
        let v653: f64 = v652 + v629;
        let v654: f64 = v94 * v653;
        let v655: f64 = v647 + v654;
        let v656: f64 = v637 + v655;
        let v657: f64 = v80 * v656;
        let v658: f64 = v632 + v657;
        let v659: f64 = v57 * v658;
        let v660: f64 = v602 - v659;
        let v661: f64 = v458 + v660;
        let v662: f64 = v23 * v661;
        let v663: f64 = v299 * v439;
        let v664: f64 = v30 * v443;
        let v665: f64 = v663 - v664;
        let v666: f64 = v302 * v427;
        let v667: f64 = v665 - v666;
        let v668: f64 = v44 * v472;
        let v669: f64 = v306 * v449;
        let v670: f64 = v668 + v669;
        let v671: f64 = v667 + v670;
        let v672: f64 = v67 * v461;
        let v673: f64 = v239 * v465;
        let v674: f64 = v672 + v673;
        let v675: f64 = v313 * v439;
        let v676: f64 = v674 + v675;
        let v677: f64 = v217 * v479;
        let v678: f64 = v84 * v503;
        let v679: f64 = v677 + v678;
        let v680: f64 = v676 - v679;
        let v681: f64 = v94 * v549;
        let v682: f64 = v91 * v584;
        let v683: f64 = v681 + v682;
        let v684: f64 = v680 + v683;
        let v685: f64 = v671 + v684;
        let v686: f64 = v57 * v656;
        let v687: f64 = v54 * v599;
        let v688: f64 = v686 + v687;
        let v689: f64 = v75 * v688;
        let v690: f64 = v685 + v689;
        let v691: f64 = v25 * v690;
        let v692: f64 = v662 - v691;
        let v693: f64 = v436 + v692;
        let v694: f64 = v333 * v434;
        let v695: f64 = v17 * v429;
        let v696: f64 = v335 * v6;
        let v697: f64 = v695 - v696;
        let v698: f64 = v694 + v697;
        let v699: f64 = v39 * v443;
        let v700: f64 = v306 * v439;
        let v701: f64 = v699 + v700;
        let v702: f64 = v343 * v449;
        let v703: f64 = v701 + v702;
        let v704: f64 = v703 + v688;
        let v705: f64 = v698 + v704;
        let v706: f64 = v18 * v705;
        let v707: f64 = v693 - v706;
        let v708: f64 = v2 * v707;
        let v709: f64 = v351 * v427;
        let v710: f64 = v3 * v429;
        let v711: f64 = v709 - v710;
        let v712: f64 = v355 * v6;
        let v713: f64 = v711 - v712;
        let v714: f64 = v17 * v453;
        let v715: f64 = v713 + v714;
        let v716: f64 = v302 * v439;
        let v717: f64 = v36 * v443;
        let v718: f64 = v716 - v717;
        let v719: f64 = v363 * v427;
        let v720: f64 = v718 - v719;
        let v721: f64 = v306 * v455;
        let v722: f64 = v39 * v472;
        let v723: f64 = v721 + v722;
        let v724: f64 = v720 - v723;
        let v725: f64 = v57 * v601;
        let v726: f64 = v54 * v658;
        let v727: f64 = v725 + v726;
        let v728: f64 = v724 - v727;
        let v729: f64 = v84 * v461;
        let v730: f64 = v217 * v465;
        let v731: f64 = v729 - v730;
        let v732: f64 = v221 * v482;
        let v733: f64 = v731 - v732;
        let v734: f64 = v94 * v646;
        let v735: f64 = v91 * v653;
        let v736: f64 = v734 - v735;
        let v737: f64 = v733 + v736;
        let v738: f64 = v75 * v737;
        let v739: f64 = v728 + v738;
        let v740: f64 = v715 - v739;
        let v741: f64 = v343 * v472;
        let v742: f64 = v44 * v439;
        let v743: f64 = v39 * v427;
        let v744: f64 = v742 + v743;
        let v745: f64 = v741 + v744;
        let v746: f64 = v54 * v656;
        let v747: f64 = v57 * v599;
        let v748: f64 = v746 - v747;
        let v749: f64 = v745 + v748;
        let v750: f64 = v25 * v749;
        let v751: f64 = v343 * v455;
        let v752: f64 = v306 * v427;
        let v753: f64 = v44 * v443;
        let v754: f64 = v752 - v753;
        let v755: f64 = v751 + v754;
        let v756: f64 = v737 - v755;
        let v757: f64 = v23 * v756;
        let v758: f64 = v750 + v757;
        let v759: f64 = v40 * v758;
        let v760: f64 = v740 - v759;
        let v761: f64 = v333 * v453;
        let v762: f64 = v17 * v427;
        let v763: f64 = v408 * v6;
        let v764: f64 = v762 + v763;
        let v765: f64 = v761 + v764;
        let v766: f64 = v23 * v749;
        let v767: f64 = v25 * v756;
        let v768: f64 = v766 - v767;
        let v769: f64 = v765 + v768;
        let v770: f64 = v18 * v769;
        let v771: f64 = v760 + v770;
        let v772: f64 = v4 * v771;
        let v773: f64 = v708 - v772;
        let v774: f64 = v422 * v14;
        let v775: f64 = v420 * v6;
        let v776: f64 = v774 - v775;
        let v777: f64 = v773 - v776;
        let v778: f64 = v6 * v777;
        let v779: f64 = v426 + v778;
        let v780: f64 = params[17];
        let v781: f64 = v780 * v6;
        let v782: f64 = v421 - v781;
        let v783: f64 = v355 * v427;
        let v784: f64 = v13 * v429;
        let v785: f64 = v783 - v784;
        let v786: f64 = params[29];
        let v787: f64 = v786 * v6;
        let v788: f64 = v785 - v787;
        let v789: f64 = v335 * v434;
        let v790: f64 = v408 * v453;
        let v791: f64 = v789 - v790;
        (
            v631,
            v661,
            v684,
            v690,
            v704,
            v707,
            v739,
            v771,
            v775,
            v779,
            v780,
            v782,
            v786,
            v788,
            v791,
        )
    };
    let (
        v798,
        v822,
        v823,
        v824,
        v825,
        v827,
        v830,
        v832,
        v833,
        v835,
        v843,
        v845,
        v848,
        v851,
        v855,
        v862,
        v869,
        v872,
        v878,
        v882,
        v893,
        v895,
        v901,
        v905,
        v911,
        v918,
        v923,
        v936,
        v939,
        v958,
        v964,
        v970,
        v974,
        v977,
        v989,
    ) = {
        let v792: f64 = v788 + v791;
        let v793: f64 = v25 * v661;
        let v794: f64 = v23 * v690;
        let v795: f64 = v793 + v794;
        let v796: f64 = v792 + v795;
        let v797: f64 = v40 * v704;
        let v798: f64 = v796 + v797;
        let v799: f64 = v782 + v798;
        let v800: f64 = v14 * v799;
        let v801: f64 = v780 * v14;
        let v802: f64 = v801 + v775;
        let v803: f64 = v355 * v7;
        let v804: f64 = v13 * v10;
        let v805: f64 = v803 - v804;
        let v806: f64 = v786 * v14;
        let v807: f64 = v805 + v806;
        let v808: f64 = v335 * v19;
        let v809: f64 = v408 * v47;
        let v810: f64 = v808 - v809;
        let v811: f64 = v807 + v810;
        let v812: f64 = v25 * v296;
        let v813: f64 = v23 * v329;
        let v814: f64 = v812 + v813;
        let v815: f64 = v811 + v814;
        let v816: f64 = v40 * v346;
        let v817: f64 = v815 - v816;
        let v818: f64 = v802 + v817;
        let v819: f64 = v818 * v6;
        let v820: f64 = v800 - v819;
        let v821: f64 = v779 - v820;
        let v822: f64 = v0 * v821;
        let v823: f64 = qd[1];
        let v824: f64 = v822 * v823;
        let v825: f64 = v6 * v2;
        let v826: f64 = v3 * v825;
        let v827: f64 = v6 * v4;
        let v828: f64 = v9 * v827;
        let v829: f64 = v826 + v828;
        let v830: f64 = v18 * v827;
        let v831: f64 = v17 * v830;
        let v832: f64 = v829 + v831;
        let v833: f64 = v23 * v827;
        let v834: f64 = v24 * v833;
        let v835: f64 = v25 * v827;
        let v836: f64 = v30 * v835;
        let v837: f64 = v834 - v836;
        let v838: f64 = v36 * v825;
        let v839: f64 = v837 - v838;
        let v840: f64 = v39 * v830;
        let v841: f64 = v40 * v825;
        let v842: f64 = v23 * v841;
        let v843: f64 = v18 * v825;
        let v844: f64 = v25 * v843;
        let v845: f64 = v842 + v844;
        let v846: f64 = v44 * v845;
        let v847: f64 = v840 + v846;
        let v848: f64 = v839 + v847;
        let v849: f64 = v54 * v833;
        let v850: f64 = v57 * v825;
        let v851: f64 = v849 + v850;
        let v852: f64 = v55 * v851;
        let v853: f64 = v57 * v833;
        let v854: f64 = v54 * v825;
        let v855: f64 = v853 - v854;
        let v856: f64 = v61 * v855;
        let v857: f64 = v852 - v856;
        let v858: f64 = v67 * v835;
        let v859: f64 = v857 - v858;
        let v860: f64 = v23 * v843;
        let v861: f64 = v25 * v841;
        let v862: f64 = v860 - v861;
        let v863: f64 = v57 * v862;
        let v864: f64 = v75 * v835;
        let v865: f64 = v864 + v830;
        let v866: f64 = v54 * v865;
        let v867: f64 = v863 + v866;
        let v868: f64 = v80 * v851;
        let v869: f64 = v867 + v868;
        let v870: f64 = v70 * v869;
        let v871: f64 = v75 * v825;
        let v872: f64 = v845 + v871;
        let v873: f64 = v84 * v872;
        let v874: f64 = v870 - v873;
        let v875: f64 = v859 + v874;
        let v876: f64 = v91 * v851;
        let v877: f64 = v94 * v835;
        let v878: f64 = v876 - v877;
        let v879: f64 = v92 * v878;
        let v880: f64 = v91 * v835;
        let v881: f64 = v94 * v851;
        let v882: f64 = v880 + v881;
        let v883: f64 = v98 * v882;
        let v884: f64 = v879 - v883;
        let v885: f64 = v104 * v855;
        let v886: f64 = v884 + v885;
        let v887: f64 = v107 * v869;
        let v888: f64 = v91 * v872;
        let v889: f64 = v54 * v862;
        let v890: f64 = v57 * v865;
        let v891: f64 = v889 - v890;
        let v892: f64 = v80 * v855;
        let v893: f64 = v891 - v892;
        let v894: f64 = v94 * v893;
        let v895: f64 = v888 + v894;
        let v896: f64 = v109 * v895;
        let v897: f64 = v887 + v896;
        let v898: f64 = v886 + v897;
        let v899: f64 = v122 * v878;
        let v900: f64 = v125 * v855;
        let v901: f64 = v899 + v900;
        let v902: f64 = v123 * v901;
        let v903: f64 = v122 * v855;
        let v904: f64 = v125 * v878;
        let v905: f64 = v903 - v904;
        let v906: f64 = v129 * v905;
        let v907: f64 = v902 + v906;
        let v908: f64 = v135 * v882;
        let v909: f64 = v907 + v908;
        let v910: f64 = v139 * v855;
        let v911: f64 = v910 - v895;
        let v912: f64 = v138 * v911;
        let v913: f64 = v139 * v882;
        let v914: f64 = v869 + v913;
        let v915: f64 = v122 * v914;
        let v916: f64 = v91 * v893;
        let v917: f64 = v94 * v872;
        let v918: f64 = v916 - v917;
        let v919: f64 = v125 * v918;
        let v920: f64 = v915 - v919;
        let v921: f64 = v143 * v920;
        let v922: f64 = v912 + v921;
        let v923: f64 = v909 - v922;
        let v924: f64 = v122 * v923;
        let v925: f64 = v129 * v901;
        let v926: f64 = v157 * v905;
        let v927: f64 = v925 + v926;
        let v928: f64 = v160 * v882;
        let v929: f64 = v927 + v928;
        let v930: f64 = v122 * v918;
        let v931: f64 = v125 * v914;
        let v932: f64 = v930 + v931;
        let v933: f64 = v143 * v932;
        let v934: f64 = v167 * v911;
        let v935: f64 = v933 + v934;
        let v936: f64 = v929 + v935;
        let v937: f64 = v125 * v936;
        let v938: f64 = v924 - v937;
        let v939: f64 = v898 + v938;
        let v940: f64 = v91 * v939;
        let v941: f64 = v98 * v878;
        let v942: f64 = v176 * v882;
        let v943: f64 = v941 - v942;
        let v944: f64 = v179 * v855;
        let v945: f64 = v943 + v944;
        let v946: f64 = v109 * v918;
        let v947: f64 = v183 * v869;
        let v948: f64 = v946 - v947;
        let v949: f64 = v945 + v948;
        let v950: f64 = v135 * v901;
        let v951: f64 = v160 * v905;
        let v952: f64 = v950 + v951;
        let v953: f64 = v190 * v882;
        let v954: f64 = v952 + v953;
        let v955: f64 = v167 * v920;
        let v956: f64 = v138 * v932;
        let v957: f64 = v955 - v956;
        let v958: f64 = v954 + v957;
        let v959: f64 = v949 - v958;
        let v960: f64 = v198 * v932;
        let v961: f64 = v143 * v905;
        let v962: f64 = v138 * v882;
        let v963: f64 = v961 - v962;
        let v964: f64 = v960 + v963;
        let v965: f64 = v125 * v964;
        let v966: f64 = v198 * v920;
        let v967: f64 = v143 * v901;
        let v968: f64 = v167 * v882;
        let v969: f64 = v967 - v968;
        let v970: f64 = v966 - v969;
        let v971: f64 = v122 * v970;
        let v972: f64 = v965 + v971;
        let v973: f64 = v139 * v972;
        let v974: f64 = v959 - v973;
        let v975: f64 = v94 * v974;
        let v976: f64 = v940 - v975;
        let v977: f64 = v875 + v976;
        let v978: f64 = v217 * v835;
        let v979: f64 = v70 * v851;
        let v980: f64 = v978 + v979;
        let v981: f64 = v221 * v869;
        let v982: f64 = v980 + v981;
        let v983: f64 = v224 * v869;
        let v984: f64 = v107 * v878;
        let v985: f64 = v183 * v882;
        let v986: f64 = v984 + v985;
        let v987: f64 = v983 + v986;
        let v988: f64 = v987 + v972;
        let v989: f64 = v982 + v988;
        (
            v798,
            v822,
            v823,
            v824,
            v825,
            v827,
            v830,
            v832,
            v833,
            v835,
            v843,
            v845,
            v848,
            v851,
            v855,
            v862,
            v869,
            v872,
            v878,
            v882,
            v893,
            v895,
            v901,
            v905,
            v911,
            v918,
            v923,
            v936,
            v939,
            v958,
            v964,
            v970,
            v974,
            v977,
            v989,
        )
    };
    let (
        v1021,
        v1074,
        v1095,
        v1128,
        v1158,
        v1175,
        v1178,
        v1179,
        v1181,
        v1184,
        v1185,
        v1186,
        v1187,
    ) = {
        let v990: f64 = v80 * v989;
        let v991: f64 = v977 + v990;
        let v992: f64 = v54 * v991;
        let v993: f64 = v61 * v851;
        let v994: f64 = v236 * v855;
        let v995: f64 = v993 - v994;
        let v996: f64 = v239 * v835;
        let v997: f64 = v995 - v996;
        let v998: f64 = v70 * v893;
        let v999: f64 = v217 * v872;
        let v1000: f64 = v998 + v999;
        let v1001: f64 = v997 + v1000;
        let v1002: f64 = v104 * v878;
        let v1003: f64 = v179 * v882;
        let v1004: f64 = v1002 - v1003;
        let v1005: f64 = v249 * v855;
        let v1006: f64 = v1004 + v1005;
        let v1007: f64 = v183 * v895;
        let v1008: f64 = v107 * v918;
        let v1009: f64 = v1007 + v1008;
        let v1010: f64 = v1006 - v1009;
        let v1011: f64 = v125 * v923;
        let v1012: f64 = v122 * v936;
        let v1013: f64 = v1011 + v1012;
        let v1014: f64 = v1010 + v1013;
        let v1015: f64 = v138 * v901;
        let v1016: f64 = v167 * v905;
        let v1017: f64 = v1015 - v1016;
        let v1018: f64 = v198 * v911;
        let v1019: f64 = v1017 - v1018;
        let v1020: f64 = v139 * v1019;
        let v1021: f64 = v1014 - v1020;
        let v1022: f64 = v1001 - v1021;
        let v1023: f64 = v221 * v893;
        let v1024: f64 = v70 * v855;
        let v1025: f64 = v84 * v835;
        let v1026: f64 = v1024 - v1025;
        let v1027: f64 = v1023 - v1026;
        let v1028: f64 = v224 * v918;
        let v1029: f64 = v109 * v882;
        let v1030: f64 = v107 * v855;
        let v1031: f64 = v1029 + v1030;
        let v1032: f64 = v1028 - v1031;
        let v1033: f64 = v122 * v964;
        let v1034: f64 = v125 * v970;
        let v1035: f64 = v1033 - v1034;
        let v1036: f64 = v1032 + v1035;
        let v1037: f64 = v91 * v1036;
        let v1038: f64 = v183 * v855;
        let v1039: f64 = v109 * v878;
        let v1040: f64 = v1038 - v1039;
        let v1041: f64 = v224 * v895;
        let v1042: f64 = v1040 - v1041;
        let v1043: f64 = v1042 - v1019;
        let v1044: f64 = v94 * v1043;
        let v1045: f64 = v1037 - v1044;
        let v1046: f64 = v1027 + v1045;
        let v1047: f64 = v80 * v1046;
        let v1048: f64 = v1022 + v1047;
        let v1049: f64 = v57 * v1048;
        let v1050: f64 = v992 - v1049;
        let v1051: f64 = v848 + v1050;
        let v1052: f64 = v23 * v1051;
        let v1053: f64 = v30 * v833;
        let v1054: f64 = v299 * v835;
        let v1055: f64 = v1053 - v1054;
        let v1056: f64 = v302 * v825;
        let v1057: f64 = v1055 - v1056;
        let v1058: f64 = v44 * v862;
        let v1059: f64 = v306 * v830;
        let v1060: f64 = v1058 - v1059;
        let v1061: f64 = v1057 + v1060;
        let v1062: f64 = v67 * v851;
        let v1063: f64 = v239 * v855;
        let v1064: f64 = v1062 - v1063;
        let v1065: f64 = v313 * v835;
        let v1066: f64 = v1064 - v1065;
        let v1067: f64 = v217 * v869;
        let v1068: f64 = v84 * v893;
        let v1069: f64 = v1067 + v1068;
        let v1070: f64 = v1066 - v1069;
        let v1071: f64 = v94 * v939;
        let v1072: f64 = v91 * v974;
        let v1073: f64 = v1071 + v1072;
        let v1074: f64 = v1070 + v1073;
        let v1075: f64 = v1061 + v1074;
        let v1076: f64 = v57 * v1046;
        let v1077: f64 = v54 * v989;
        let v1078: f64 = v1076 - v1077;
        let v1079: f64 = v75 * v1078;
        let v1080: f64 = v1075 + v1079;
        let v1081: f64 = v25 * v1080;
        let v1082: f64 = v1052 - v1081;
        let v1083: f64 = v832 + v1082;
        let v1084: f64 = v333 * v830;
        let v1085: f64 = v17 * v827;
        let v1086: f64 = v1084 + v1085;
        let v1087: f64 = v39 * v833;
        let v1088: f64 = v306 * v835;
        let v1089: f64 = v1087 + v1088;
        let v1090: f64 = v343 * v830;
        let v1091: f64 = v1089 + v1090;
        let v1092: f64 = v1091 - v1078;
        let v1093: f64 = v1086 + v1092;
        let v1094: f64 = v18 * v1093;
        let v1095: f64 = v1083 + v1094;
        let v1096: f64 = v2 * v1095;
        let v1097: f64 = v349 * v4;
        let v1098: f64 = v1096 - v1097;
        let v1099: f64 = v417 * v2;
        let v1100: f64 = v351 * v825;
        let v1101: f64 = v3 * v827;
        let v1102: f64 = v1100 + v1101;
        let v1103: f64 = v17 * v843;
        let v1104: f64 = v1102 + v1103;
        let v1105: f64 = v36 * v833;
        let v1106: f64 = v302 * v835;
        let v1107: f64 = v1105 - v1106;
        let v1108: f64 = v363 * v825;
        let v1109: f64 = v1107 - v1108;
        let v1110: f64 = v306 * v845;
        let v1111: f64 = v39 * v862;
        let v1112: f64 = v1110 + v1111;
        let v1113: f64 = v1109 - v1112;
        let v1114: f64 = v57 * v991;
        let v1115: f64 = v54 * v1048;
        let v1116: f64 = v1114 + v1115;
        let v1117: f64 = v1113 - v1116;
        let v1118: f64 = v84 * v851;
        let v1119: f64 = v217 * v855;
        let v1120: f64 = v1118 + v1119;
        let v1121: f64 = v221 * v872;
        let v1122: f64 = v1120 - v1121;
        let v1123: f64 = v94 * v1036;
        let v1124: f64 = v91 * v1043;
        let v1125: f64 = v1123 + v1124;
        let v1126: f64 = v1122 + v1125;
        let v1127: f64 = v75 * v1126;
        let v1128: f64 = v1117 + v1127;
        let v1129: f64 = v1104 - v1128;
        let v1130: f64 = v343 * v862;
        let v1131: f64 = v39 * v825;
        let v1132: f64 = v44 * v835;
        let v1133: f64 = v1131 - v1132;
        let v1134: f64 = v1130 + v1133;
        let v1135: f64 = v54 * v1046;
        let v1136: f64 = v57 * v989;
        let v1137: f64 = v1135 + v1136;
        let v1138: f64 = v1134 + v1137;
        let v1139: f64 = v25 * v1138;
        let v1140: f64 = v343 * v845;
        let v1141: f64 = v306 * v825;
        let v1142: f64 = v44 * v833;
        let v1143: f64 = v1141 + v1142;
        let v1144: f64 = v1140 + v1143;
        let v1145: f64 = v1126 - v1144;
        let v1146: f64 = v23 * v1145;
        let v1147: f64 = v1139 + v1146;
        let v1148: f64 = v40 * v1147;
        let v1149: f64 = v1129 - v1148;
        let v1150: f64 = v333 * v843;
        let v1151: f64 = v17 * v825;
        let v1152: f64 = v1150 + v1151;
        let v1153: f64 = v23 * v1138;
        let v1154: f64 = v25 * v1145;
        let v1155: f64 = v1153 - v1154;
        let v1156: f64 = v1152 + v1155;
        let v1157: f64 = v18 * v1156;
        let v1158: f64 = v1149 + v1157;
        let v1159: f64 = v4 * v1158;
        let v1160: f64 = v1099 + v1159;
        let v1161: f64 = v1098 - v1160;
        let v1162: f64 = v6 * v1161;
        let v1163: f64 = v355 * v825;
        let v1164: f64 = v13 * v827;
        let v1165: f64 = v1163 + v1164;
        let v1166: f64 = v335 * v830;
        let v1167: f64 = v408 * v843;
        let v1168: f64 = v1166 + v1167;
        let v1169: f64 = v1165 - v1168;
        let v1170: f64 = v25 * v1051;
        let v1171: f64 = v23 * v1080;
        let v1172: f64 = v1170 + v1171;
        let v1173: f64 = v1169 + v1172;
        let v1174: f64 = v40 * v1092;
        let v1175: f64 = v1173 - v1174;
        let v1176: f64 = v14 * v1175;
        let v1177: f64 = v1162 - v1176;
        let v1178: f64 = v0 * v1177;
        let v1179: f64 = qd[2];
        let v1180: f64 = v1178 * v1179;
        let v1181: f64 = v824 + v1180;
        let v1182: f64 = v14 * v23;
        let v1183: f64 = v10 * v25;
        let v1184: f64 = v1182 + v1183;
        let v1185: f64 = v24 * v1184;
        let v1186: f64 = v10 * v23;
        let v1187: f64 = v14 * v25;
        (
            v1021,
            v1074,
            v1095,
            v1128,
            v1158,
            v1175,
            v1178,
            v1179,
            v1181,
            v1184,
            v1185,
            v1186,
            v1187,
        )
    };
    let (
        v1188,
        v1193,
        v1195,
        v1196,
        v1198,
        v1206,
        v1211,
        v1233,
        v1279,
        v1298,
        v1314,
        v1329,
        v1331,
        v1332,
        v1361,
        v1362,
        v1367,
        v1376,
        v1383,
        v1385,
    ) = {
        let v1188: f64 = v1186 - v1187;
        let v1189: f64 = v30 * v1188;
        let v1190: f64 = v1185 + v1189;
        let v1191: f64 = v47 * v23;
        let v1192: f64 = v45 * v25;
        let v1193: f64 = v1191 - v1192;
        let v1194: f64 = v44 * v1193;
        let v1195: f64 = v1190 + v1194;
        let v1196: f64 = v54 * v1184;
        let v1197: f64 = v55 * v1196;
        let v1198: f64 = v57 * v1184;
        let v1199: f64 = v61 * v1198;
        let v1200: f64 = v1197 - v1199;
        let v1201: f64 = v67 * v1188;
        let v1202: f64 = v1200 + v1201;
        let v1203: f64 = v80 * v1196;
        let v1204: f64 = v47 * v25;
        let v1205: f64 = v45 * v23;
        let v1206: f64 = v1204 + v1205;
        let v1207: f64 = v57 * v1206;
        let v1208: f64 = v75 * v1188;
        let v1209: f64 = v54 * v1208;
        let v1210: f64 = v1207 + v1209;
        let v1211: f64 = v1203 - v1210;
        let v1212: f64 = v70 * v1211;
        let v1213: f64 = v84 * v1193;
        let v1214: f64 = v1212 - v1213;
        let v1215: f64 = v1202 + v1214;
        let v1216: f64 = v91 * v1196;
        let v1217: f64 = v94 * v1188;
        let v1218: f64 = v1216 + v1217;
        let v1219: f64 = v92 * v1218;
        let v1220: f64 = v91 * v1188;
        let v1221: f64 = v94 * v1196;
        let v1222: f64 = v1220 - v1221;
        let v1223: f64 = v98 * v1222;
        let v1224: f64 = v1219 + v1223;
        let v1225: f64 = v104 * v1198;
        let v1226: f64 = v1224 + v1225;
        let v1227: f64 = v107 * v1211;
        let v1228: f64 = v91 * v1193;
        let v1229: f64 = v57 * v1208;
        let v1230: f64 = v54 * v1206;
        let v1231: f64 = v1229 - v1230;
        let v1232: f64 = v80 * v1198;
        let v1233: f64 = v1231 - v1232;
        let v1234: f64 = v94 * v1233;
        let v1235: f64 = v1228 + v1234;
        let v1236: f64 = v109 * v1235;
        let v1237: f64 = v1227 + v1236;
        let v1238: f64 = v1226 + v1237;
        let v1239: f64 = v122 * v1218;
        let v1240: f64 = v125 * v1198;
        let v1241: f64 = v1239 + v1240;
        let v1242: f64 = v123 * v1241;
        let v1243: f64 = v122 * v1198;
        let v1244: f64 = v125 * v1218;
        let v1245: f64 = v1243 - v1244;
        let v1246: f64 = v129 * v1245;
        let v1247: f64 = v1242 + v1246;
        let v1248: f64 = v135 * v1222;
        let v1249: f64 = v1247 - v1248;
        let v1250: f64 = v139 * v1198;
        let v1251: f64 = v1250 - v1235;
        let v1252: f64 = v138 * v1251;
        let v1253: f64 = v139 * v1222;
        let v1254: f64 = v1211 - v1253;
        let v1255: f64 = v122 * v1254;
        let v1256: f64 = v91 * v1233;
        let v1257: f64 = v94 * v1193;
        let v1258: f64 = v1256 - v1257;
        let v1259: f64 = v125 * v1258;
        let v1260: f64 = v1255 - v1259;
        let v1261: f64 = v143 * v1260;
        let v1262: f64 = v1252 + v1261;
        let v1263: f64 = v1249 - v1262;
        let v1264: f64 = v122 * v1263;
        let v1265: f64 = v129 * v1241;
        let v1266: f64 = v157 * v1245;
        let v1267: f64 = v1265 + v1266;
        let v1268: f64 = v160 * v1222;
        let v1269: f64 = v1267 - v1268;
        let v1270: f64 = v122 * v1258;
        let v1271: f64 = v125 * v1254;
        let v1272: f64 = v1270 + v1271;
        let v1273: f64 = v143 * v1272;
        let v1274: f64 = v167 * v1251;
        let v1275: f64 = v1273 + v1274;
        let v1276: f64 = v1269 + v1275;
        let v1277: f64 = v125 * v1276;
        let v1278: f64 = v1264 - v1277;
        let v1279: f64 = v1238 + v1278;
        let v1280: f64 = v91 * v1279;
        let v1281: f64 = v98 * v1218;
        let v1282: f64 = v176 * v1222;
        let v1283: f64 = v1281 + v1282;
        let v1284: f64 = v179 * v1198;
        let v1285: f64 = v1283 + v1284;
        let v1286: f64 = v109 * v1258;
        let v1287: f64 = v183 * v1211;
        let v1288: f64 = v1286 - v1287;
        let v1289: f64 = v1285 + v1288;
        let v1290: f64 = v135 * v1241;
        let v1291: f64 = v160 * v1245;
        let v1292: f64 = v1290 + v1291;
        let v1293: f64 = v190 * v1222;
        let v1294: f64 = v1292 - v1293;
        let v1295: f64 = v167 * v1260;
        let v1296: f64 = v138 * v1272;
        let v1297: f64 = v1295 - v1296;
        let v1298: f64 = v1294 + v1297;
        let v1299: f64 = v1289 - v1298;
        let v1300: f64 = v198 * v1272;
        let v1301: f64 = v143 * v1245;
        let v1302: f64 = v138 * v1222;
        let v1303: f64 = v1301 + v1302;
        let v1304: f64 = v1300 + v1303;
        let v1305: f64 = v125 * v1304;
        let v1306: f64 = v198 * v1260;
        let v1307: f64 = v167 * v1222;
        let v1308: f64 = v143 * v1241;
        let v1309: f64 = v1307 + v1308;
        let v1310: f64 = v1306 - v1309;
        let v1311: f64 = v122 * v1310;
        let v1312: f64 = v1305 + v1311;
        let v1313: f64 = v139 * v1312;
        let v1314: f64 = v1299 - v1313;
        let v1315: f64 = v94 * v1314;
        let v1316: f64 = v1280 - v1315;
        let v1317: f64 = v1215 + v1316;
        let v1318: f64 = v217 * v1188;
        let v1319: f64 = v70 * v1196;
        let v1320: f64 = v1318 - v1319;
        let v1321: f64 = v221 * v1211;
        let v1322: f64 = v1320 - v1321;
        let v1323: f64 = v224 * v1211;
        let v1324: f64 = v107 * v1218;
        let v1325: f64 = v183 * v1222;
        let v1326: f64 = v1324 - v1325;
        let v1327: f64 = v1323 + v1326;
        let v1328: f64 = v1327 + v1312;
        let v1329: f64 = v1322 - v1328;
        let v1330: f64 = v80 * v1329;
        let v1331: f64 = v1317 - v1330;
        let v1332: f64 = v54 * v1331;
        let v1333: f64 = v61 * v1196;
        let v1334: f64 = v236 * v1198;
        let v1335: f64 = v1333 - v1334;
        let v1336: f64 = v239 * v1188;
        let v1337: f64 = v1335 + v1336;
        let v1338: f64 = v70 * v1233;
        let v1339: f64 = v217 * v1193;
        let v1340: f64 = v1338 + v1339;
        let v1341: f64 = v1337 + v1340;
        let v1342: f64 = v104 * v1218;
        let v1343: f64 = v179 * v1222;
        let v1344: f64 = v1342 + v1343;
        let v1345: f64 = v249 * v1198;
        let v1346: f64 = v1344 + v1345;
        let v1347: f64 = v183 * v1235;
        let v1348: f64 = v107 * v1258;
        let v1349: f64 = v1347 + v1348;
        let v1350: f64 = v1346 - v1349;
        let v1351: f64 = v125 * v1263;
        let v1352: f64 = v122 * v1276;
        let v1353: f64 = v1351 + v1352;
        let v1354: f64 = v1350 + v1353;
        let v1355: f64 = v138 * v1241;
        let v1356: f64 = v167 * v1245;
        let v1357: f64 = v1355 - v1356;
        let v1358: f64 = v198 * v1251;
        let v1359: f64 = v1357 - v1358;
        let v1360: f64 = v139 * v1359;
        let v1361: f64 = v1354 - v1360;
        let v1362: f64 = v1341 - v1361;
        let v1363: f64 = v221 * v1233;
        let v1364: f64 = v70 * v1198;
        let v1365: f64 = v84 * v1188;
        let v1366: f64 = v1364 + v1365;
        let v1367: f64 = v1363 - v1366;
        let v1368: f64 = v224 * v1258;
        let v1369: f64 = v109 * v1222;
        let v1370: f64 = v107 * v1198;
        let v1371: f64 = v1369 - v1370;
        let v1372: f64 = v1368 + v1371;
        let v1373: f64 = v122 * v1304;
        let v1374: f64 = v125 * v1310;
        let v1375: f64 = v1373 - v1374;
        let v1376: f64 = v1372 + v1375;
        let v1377: f64 = v91 * v1376;
        let v1378: f64 = v183 * v1198;
        let v1379: f64 = v109 * v1218;
        let v1380: f64 = v1378 - v1379;
        let v1381: f64 = v224 * v1235;
        let v1382: f64 = v1380 - v1381;
        let v1383: f64 = v1382 - v1359;
        let v1384: f64 = v94 * v1383;
        let v1385: f64 = v1377 - v1384;
        (
            v1188,
            v1193,
            v1195,
            v1196,
            v1198,
            v1206,
            v1211,
            v1233,
            v1279,
            v1298,
            v1314,
            v1329,
            v1331,
            v1332,
            v1361,
            v1362,
            v1367,
            v1376,
            v1383,
            v1385,
        )
    };
    let (
        v1413,
        v1428,
        v1470,
        v1480,
        v1492,
        v1495,
        v1496,
        v1498,
        v1501,
        v1505,
        v1512,
        v1514,
        v1515,
        v1517,
        v1527,
        v1528,
        v1534,
        v1538,
        v1544,
        v1549,
        v1551,
        v1554,
        v1563,
        v1567,
        v1570,
        v1571,
        v1580,
        v1583,
    ) = {
        let v1386: f64 = v1367 + v1385;
        let v1387: f64 = v80 * v1386;
        let v1388: f64 = v1362 + v1387;
        let v1389: f64 = v57 * v1388;
        let v1390: f64 = v1332 - v1389;
        let v1391: f64 = v1195 + v1390;
        let v1392: f64 = v23 * v1391;
        let v1393: f64 = v296 * v25;
        let v1394: f64 = v1392 - v1393;
        let v1395: f64 = v329 * v23;
        let v1396: f64 = v30 * v1184;
        let v1397: f64 = v299 * v1188;
        let v1398: f64 = v1396 + v1397;
        let v1399: f64 = v44 * v1206;
        let v1400: f64 = v1398 - v1399;
        let v1401: f64 = v67 * v1196;
        let v1402: f64 = v239 * v1198;
        let v1403: f64 = v1401 - v1402;
        let v1404: f64 = v313 * v1188;
        let v1405: f64 = v1403 + v1404;
        let v1406: f64 = v217 * v1211;
        let v1407: f64 = v84 * v1233;
        let v1408: f64 = v1406 + v1407;
        let v1409: f64 = v1405 - v1408;
        let v1410: f64 = v94 * v1279;
        let v1411: f64 = v91 * v1314;
        let v1412: f64 = v1410 + v1411;
        let v1413: f64 = v1409 + v1412;
        let v1414: f64 = v1400 + v1413;
        let v1415: f64 = v57 * v1386;
        let v1416: f64 = v54 * v1329;
        let v1417: f64 = v1415 + v1416;
        let v1418: f64 = v75 * v1417;
        let v1419: f64 = v1414 + v1418;
        let v1420: f64 = v25 * v1419;
        let v1421: f64 = v1395 + v1420;
        let v1422: f64 = v1394 - v1421;
        let v1423: f64 = v39 * v1184;
        let v1424: f64 = v306 * v1188;
        let v1425: f64 = v1423 - v1424;
        let v1426: f64 = v1425 - v1417;
        let v1427: f64 = v18 * v1426;
        let v1428: f64 = v1422 + v1427;
        let v1429: f64 = v2 * v1428;
        let v1430: f64 = v44 * v1188;
        let v1431: f64 = v343 * v1206;
        let v1432: f64 = v1430 - v1431;
        let v1433: f64 = v54 * v1386;
        let v1434: f64 = v57 * v1329;
        let v1435: f64 = v1433 - v1434;
        let v1436: f64 = v1432 + v1435;
        let v1437: f64 = v23 * v1436;
        let v1438: f64 = v394 * v25;
        let v1439: f64 = v1437 - v1438;
        let v1440: f64 = v401 * v23;
        let v1441: f64 = v84 * v1196;
        let v1442: f64 = v217 * v1198;
        let v1443: f64 = v1441 + v1442;
        let v1444: f64 = v221 * v1193;
        let v1445: f64 = v1443 - v1444;
        let v1446: f64 = v94 * v1376;
        let v1447: f64 = v91 * v1383;
        let v1448: f64 = v1446 + v1447;
        let v1449: f64 = v1445 + v1448;
        let v1450: f64 = v343 * v1193;
        let v1451: f64 = v44 * v1184;
        let v1452: f64 = v1450 + v1451;
        let v1453: f64 = v1449 - v1452;
        let v1454: f64 = v25 * v1453;
        let v1455: f64 = v1440 + v1454;
        let v1456: f64 = v1439 - v1455;
        let v1457: f64 = v18 * v1456;
        let v1458: f64 = v36 * v1184;
        let v1459: f64 = v302 * v1188;
        let v1460: f64 = v1458 + v1459;
        let v1461: f64 = v306 * v1193;
        let v1462: f64 = v39 * v1206;
        let v1463: f64 = v1461 - v1462;
        let v1464: f64 = v1460 - v1463;
        let v1465: f64 = v57 * v1331;
        let v1466: f64 = v54 * v1388;
        let v1467: f64 = v1465 + v1466;
        let v1468: f64 = v1464 - v1467;
        let v1469: f64 = v75 * v1449;
        let v1470: f64 = v1468 + v1469;
        let v1471: f64 = v394 * v23;
        let v1472: f64 = v25 * v1436;
        let v1473: f64 = v1471 + v1472;
        let v1474: f64 = v23 * v1453;
        let v1475: f64 = v401 * v25;
        let v1476: f64 = v1474 - v1475;
        let v1477: f64 = v1473 + v1476;
        let v1478: f64 = v40 * v1477;
        let v1479: f64 = v1470 + v1478;
        let v1480: f64 = v1457 - v1479;
        let v1481: f64 = v4 * v1480;
        let v1482: f64 = v1429 - v1481;
        let v1483: f64 = v6 * v1482;
        let v1484: f64 = v296 * v23;
        let v1485: f64 = v25 * v1391;
        let v1486: f64 = v1484 + v1485;
        let v1487: f64 = v23 * v1419;
        let v1488: f64 = v329 * v25;
        let v1489: f64 = v1487 - v1488;
        let v1490: f64 = v1486 + v1489;
        let v1491: f64 = v40 * v1426;
        let v1492: f64 = v1490 - v1491;
        let v1493: f64 = v14 * v1492;
        let v1494: f64 = v1483 - v1493;
        let v1495: f64 = v0 * v1494;
        let v1496: f64 = qd[3];
        let v1497: f64 = v1495 * v1496;
        let v1498: f64 = v1181 + v1497;
        let v1499: f64 = v7 * v54;
        let v1500: f64 = v28 * v57;
        let v1501: f64 = v1499 - v1500;
        let v1502: f64 = v55 * v1501;
        let v1503: f64 = v28 * v54;
        let v1504: f64 = v7 * v57;
        let v1505: f64 = v1503 + v1504;
        let v1506: f64 = v61 * v1505;
        let v1507: f64 = v1502 - v1506;
        let v1508: f64 = v73 * v54;
        let v1509: f64 = v77 * v57;
        let v1510: f64 = v1508 + v1509;
        let v1511: f64 = v80 * v1501;
        let v1512: f64 = v1510 + v1511;
        let v1513: f64 = v70 * v1512;
        let v1514: f64 = v1507 + v1513;
        let v1515: f64 = v91 * v1501;
        let v1516: f64 = v92 * v1515;
        let v1517: f64 = v94 * v1501;
        let v1518: f64 = v98 * v1517;
        let v1519: f64 = v1516 - v1518;
        let v1520: f64 = v104 * v1505;
        let v1521: f64 = v1519 + v1520;
        let v1522: f64 = v107 * v1512;
        let v1523: f64 = v77 * v54;
        let v1524: f64 = v73 * v57;
        let v1525: f64 = v1523 - v1524;
        let v1526: f64 = v80 * v1505;
        let v1527: f64 = v1525 - v1526;
        let v1528: f64 = v94 * v1527;
        let v1529: f64 = v109 * v1528;
        let v1530: f64 = v1522 + v1529;
        let v1531: f64 = v1521 + v1530;
        let v1532: f64 = v122 * v1515;
        let v1533: f64 = v125 * v1505;
        let v1534: f64 = v1532 + v1533;
        let v1535: f64 = v123 * v1534;
        let v1536: f64 = v122 * v1505;
        let v1537: f64 = v125 * v1515;
        let v1538: f64 = v1536 - v1537;
        let v1539: f64 = v129 * v1538;
        let v1540: f64 = v1535 + v1539;
        let v1541: f64 = v135 * v1517;
        let v1542: f64 = v1540 + v1541;
        let v1543: f64 = v139 * v1505;
        let v1544: f64 = v1543 - v1528;
        let v1545: f64 = v138 * v1544;
        let v1546: f64 = v139 * v1517;
        let v1547: f64 = v1512 + v1546;
        let v1548: f64 = v122 * v1547;
        let v1549: f64 = v91 * v1527;
        let v1550: f64 = v125 * v1549;
        let v1551: f64 = v1548 - v1550;
        let v1552: f64 = v143 * v1551;
        let v1553: f64 = v1545 + v1552;
        let v1554: f64 = v1542 - v1553;
        let v1555: f64 = v122 * v1554;
        let v1556: f64 = v129 * v1534;
        let v1557: f64 = v157 * v1538;
        let v1558: f64 = v1556 + v1557;
        let v1559: f64 = v160 * v1517;
        let v1560: f64 = v1558 + v1559;
        let v1561: f64 = v122 * v1549;
        let v1562: f64 = v125 * v1547;
        let v1563: f64 = v1561 + v1562;
        let v1564: f64 = v143 * v1563;
        let v1565: f64 = v167 * v1544;
        let v1566: f64 = v1564 + v1565;
        let v1567: f64 = v1560 + v1566;
        let v1568: f64 = v125 * v1567;
        let v1569: f64 = v1555 - v1568;
        let v1570: f64 = v1531 + v1569;
        let v1571: f64 = v91 * v1570;
        let v1572: f64 = v98 * v1515;
        let v1573: f64 = v176 * v1517;
        let v1574: f64 = v1572 - v1573;
        let v1575: f64 = v179 * v1505;
        let v1576: f64 = v1574 + v1575;
        let v1577: f64 = v109 * v1549;
        let v1578: f64 = v183 * v1512;
        let v1579: f64 = v1577 - v1578;
        let v1580: f64 = v1576 + v1579;
        let v1581: f64 = v135 * v1534;
        let v1582: f64 = v160 * v1538;
        let v1583: f64 = v1581 + v1582;
        (
            v1413,
            v1428,
            v1470,
            v1480,
            v1492,
            v1495,
            v1496,
            v1498,
            v1501,
            v1505,
            v1512,
            v1514,
            v1515,
            v1517,
            v1527,
            v1528,
            v1534,
            v1538,
            v1544,
            v1549,
            v1551,
            v1554,
            v1563,
            v1567,
            v1570,
            v1571,
            v1580,
            v1583,
        )
    };
    let (
        v1589,
        v1649,
        v1689,
        v1702,
        v1730,
        v1736,
        v1744,
        v1747,
        v1748,
        v1750,
        v1753,
        v1757,
        v1762,
        v1764,
        v1765,
        v1767,
        v1771,
        v1772,
        v1776,
        v1778,
        v1781,
    ) = {
        let v1584: f64 = v190 * v1517;
        let v1585: f64 = v1583 + v1584;
        let v1586: f64 = v167 * v1551;
        let v1587: f64 = v138 * v1563;
        let v1588: f64 = v1586 - v1587;
        let v1589: f64 = v1585 + v1588;
        let v1590: f64 = v1580 - v1589;
        let v1591: f64 = v198 * v1563;
        let v1592: f64 = v143 * v1538;
        let v1593: f64 = v138 * v1517;
        let v1594: f64 = v1592 - v1593;
        let v1595: f64 = v1591 + v1594;
        let v1596: f64 = v125 * v1595;
        let v1597: f64 = v198 * v1551;
        let v1598: f64 = v143 * v1534;
        let v1599: f64 = v167 * v1517;
        let v1600: f64 = v1598 - v1599;
        let v1601: f64 = v1597 - v1600;
        let v1602: f64 = v122 * v1601;
        let v1603: f64 = v1596 + v1602;
        let v1604: f64 = v139 * v1603;
        let v1605: f64 = v1590 - v1604;
        let v1606: f64 = v94 * v1605;
        let v1607: f64 = v1571 - v1606;
        let v1608: f64 = v1514 + v1607;
        let v1609: f64 = v70 * v1501;
        let v1610: f64 = v221 * v1512;
        let v1611: f64 = v1609 + v1610;
        let v1612: f64 = v224 * v1512;
        let v1613: f64 = v107 * v1515;
        let v1614: f64 = v183 * v1517;
        let v1615: f64 = v1613 + v1614;
        let v1616: f64 = v1612 + v1615;
        let v1617: f64 = v1616 + v1603;
        let v1618: f64 = v1611 + v1617;
        let v1619: f64 = v80 * v1618;
        let v1620: f64 = v1608 + v1619;
        let v1621: f64 = v54 * v1620;
        let v1622: f64 = v233 * v57;
        let v1623: f64 = v1621 - v1622;
        let v1624: f64 = v293 * v54;
        let v1625: f64 = v61 * v1501;
        let v1626: f64 = v236 * v1505;
        let v1627: f64 = v1625 - v1626;
        let v1628: f64 = v70 * v1527;
        let v1629: f64 = v1627 + v1628;
        let v1630: f64 = v104 * v1515;
        let v1631: f64 = v179 * v1517;
        let v1632: f64 = v1630 - v1631;
        let v1633: f64 = v249 * v1505;
        let v1634: f64 = v1632 + v1633;
        let v1635: f64 = v183 * v1528;
        let v1636: f64 = v107 * v1549;
        let v1637: f64 = v1635 + v1636;
        let v1638: f64 = v1634 - v1637;
        let v1639: f64 = v125 * v1554;
        let v1640: f64 = v122 * v1567;
        let v1641: f64 = v1639 + v1640;
        let v1642: f64 = v1638 + v1641;
        let v1643: f64 = v138 * v1534;
        let v1644: f64 = v167 * v1538;
        let v1645: f64 = v1643 - v1644;
        let v1646: f64 = v198 * v1544;
        let v1647: f64 = v1645 - v1646;
        let v1648: f64 = v139 * v1647;
        let v1649: f64 = v1642 - v1648;
        let v1650: f64 = v1629 - v1649;
        let v1651: f64 = v221 * v1527;
        let v1652: f64 = v70 * v1505;
        let v1653: f64 = v1651 - v1652;
        let v1654: f64 = v224 * v1549;
        let v1655: f64 = v109 * v1517;
        let v1656: f64 = v107 * v1505;
        let v1657: f64 = v1655 + v1656;
        let v1658: f64 = v1654 - v1657;
        let v1659: f64 = v122 * v1595;
        let v1660: f64 = v125 * v1601;
        let v1661: f64 = v1659 - v1660;
        let v1662: f64 = v1658 + v1661;
        let v1663: f64 = v91 * v1662;
        let v1664: f64 = v183 * v1505;
        let v1665: f64 = v109 * v1515;
        let v1666: f64 = v1664 - v1665;
        let v1667: f64 = v224 * v1528;
        let v1668: f64 = v1666 - v1667;
        let v1669: f64 = v1668 - v1647;
        let v1670: f64 = v94 * v1669;
        let v1671: f64 = v1663 - v1670;
        let v1672: f64 = v1653 + v1671;
        let v1673: f64 = v80 * v1672;
        let v1674: f64 = v1650 + v1673;
        let v1675: f64 = v57 * v1674;
        let v1676: f64 = v1624 + v1675;
        let v1677: f64 = v1623 - v1676;
        let v1678: f64 = v23 * v1677;
        let v1679: f64 = v67 * v1501;
        let v1680: f64 = v239 * v1505;
        let v1681: f64 = v1679 - v1680;
        let v1682: f64 = v217 * v1512;
        let v1683: f64 = v84 * v1527;
        let v1684: f64 = v1682 + v1683;
        let v1685: f64 = v1681 - v1684;
        let v1686: f64 = v94 * v1570;
        let v1687: f64 = v91 * v1605;
        let v1688: f64 = v1686 + v1687;
        let v1689: f64 = v1685 + v1688;
        let v1690: f64 = v291 * v54;
        let v1691: f64 = v57 * v1672;
        let v1692: f64 = v1690 + v1691;
        let v1693: f64 = v231 * v57;
        let v1694: f64 = v54 * v1618;
        let v1695: f64 = v1693 + v1694;
        let v1696: f64 = v1692 - v1695;
        let v1697: f64 = v75 * v1696;
        let v1698: f64 = v1689 + v1697;
        let v1699: f64 = v25 * v1698;
        let v1700: f64 = v1678 - v1699;
        let v1701: f64 = v18 * v1696;
        let v1702: f64 = v1700 - v1701;
        let v1703: f64 = v2 * v1702;
        let v1704: f64 = v54 * v1672;
        let v1705: f64 = v291 * v57;
        let v1706: f64 = v1704 - v1705;
        let v1707: f64 = v231 * v54;
        let v1708: f64 = v57 * v1618;
        let v1709: f64 = v1707 - v1708;
        let v1710: f64 = v1706 - v1709;
        let v1711: f64 = v23 * v1710;
        let v1712: f64 = v84 * v1501;
        let v1713: f64 = v217 * v1505;
        let v1714: f64 = v1712 + v1713;
        let v1715: f64 = v94 * v1662;
        let v1716: f64 = v91 * v1669;
        let v1717: f64 = v1715 + v1716;
        let v1718: f64 = v1714 + v1717;
        let v1719: f64 = v25 * v1718;
        let v1720: f64 = v1711 - v1719;
        let v1721: f64 = v18 * v1720;
        let v1722: f64 = v75 * v1718;
        let v1723: f64 = v233 * v54;
        let v1724: f64 = v57 * v1620;
        let v1725: f64 = v1723 + v1724;
        let v1726: f64 = v54 * v1674;
        let v1727: f64 = v293 * v57;
        let v1728: f64 = v1726 - v1727;
        let v1729: f64 = v1725 + v1728;
        let v1730: f64 = v1722 - v1729;
        let v1731: f64 = v25 * v1710;
        let v1732: f64 = v23 * v1718;
        let v1733: f64 = v1731 + v1732;
        let v1734: f64 = v40 * v1733;
        let v1735: f64 = v1730 + v1734;
        let v1736: f64 = v1721 - v1735;
        let v1737: f64 = v4 * v1736;
        let v1738: f64 = v1703 - v1737;
        let v1739: f64 = v6 * v1738;
        let v1740: f64 = v25 * v1677;
        let v1741: f64 = v23 * v1698;
        let v1742: f64 = v1740 + v1741;
        let v1743: f64 = v40 * v1696;
        let v1744: f64 = v1742 + v1743;
        let v1745: f64 = v14 * v1744;
        let v1746: f64 = v1739 - v1745;
        let v1747: f64 = v0 * v1746;
        let v1748: f64 = qd[4];
        let v1749: f64 = v1747 * v1748;
        let v1750: f64 = v1498 + v1749;
        let v1751: f64 = v33 * v91;
        let v1752: f64 = v59 * v94;
        let v1753: f64 = v1751 - v1752;
        let v1754: f64 = v92 * v1753;
        let v1755: f64 = v33 * v94;
        let v1756: f64 = v59 * v91;
        let v1757: f64 = v1755 + v1756;
        let v1758: f64 = v98 * v1757;
        let v1759: f64 = v1754 - v1758;
        let v1760: f64 = v115 * v91;
        let v1761: f64 = v86 * v94;
        let v1762: f64 = v1760 - v1761;
        let v1763: f64 = v109 * v1762;
        let v1764: f64 = v1759 + v1763;
        let v1765: f64 = v122 * v1753;
        let v1766: f64 = v123 * v1765;
        let v1767: f64 = v125 * v1753;
        let v1768: f64 = v129 * v1767;
        let v1769: f64 = v1766 - v1768;
        let v1770: f64 = v135 * v1757;
        let v1771: f64 = v1769 + v1770;
        let v1772: f64 = v139 * v1757;
        let v1773: f64 = v122 * v1772;
        let v1774: f64 = v115 * v94;
        let v1775: f64 = v86 * v91;
        let v1776: f64 = v1774 + v1775;
        let v1777: f64 = v125 * v1776;
        let v1778: f64 = v1773 + v1777;
        let v1779: f64 = v143 * v1778;
        let v1780: f64 = v138 * v1762;
        let v1781: f64 = v1779 - v1780;
        (
            v1589,
            v1649,
            v1689,
            v1702,
            v1730,
            v1736,
            v1744,
            v1747,
            v1748,
            v1750,
            v1753,
            v1757,
            v1762,
            v1764,
            v1765,
            v1767,
            v1771,
            v1772,
            v1776,
            v1778,
            v1781,
        )
    };
    let (
        v1816,
        v1879,
        v1890,
        v1899,
        v1919,
        v1925,
        v1933,
        v1936,
        v1937,
        v1939,
        v1942,
        v1946,
        v1951,
        v1953,
        v1965,
        v1968,
        v1969,
        v1976,
        v1977,
        v1978,
        v1979,
    ) = {
        let v1782: f64 = v1771 - v1781;
        let v1783: f64 = v122 * v1782;
        let v1784: f64 = v129 * v1765;
        let v1785: f64 = v157 * v1767;
        let v1786: f64 = v1784 - v1785;
        let v1787: f64 = v160 * v1757;
        let v1788: f64 = v1786 + v1787;
        let v1789: f64 = v125 * v1772;
        let v1790: f64 = v122 * v1776;
        let v1791: f64 = v1789 - v1790;
        let v1792: f64 = v143 * v1791;
        let v1793: f64 = v167 * v1762;
        let v1794: f64 = v1792 - v1793;
        let v1795: f64 = v1788 + v1794;
        let v1796: f64 = v125 * v1795;
        let v1797: f64 = v1783 - v1796;
        let v1798: f64 = v1764 + v1797;
        let v1799: f64 = v91 * v1798;
        let v1800: f64 = v173 * v94;
        let v1801: f64 = v1799 - v1800;
        let v1802: f64 = v213 * v91;
        let v1803: f64 = v98 * v1753;
        let v1804: f64 = v176 * v1757;
        let v1805: f64 = v1803 - v1804;
        let v1806: f64 = v109 * v1776;
        let v1807: f64 = v1805 - v1806;
        let v1808: f64 = v135 * v1765;
        let v1809: f64 = v160 * v1767;
        let v1810: f64 = v1808 - v1809;
        let v1811: f64 = v190 * v1757;
        let v1812: f64 = v1810 + v1811;
        let v1813: f64 = v167 * v1778;
        let v1814: f64 = v138 * v1791;
        let v1815: f64 = v1813 - v1814;
        let v1816: f64 = v1812 + v1815;
        let v1817: f64 = v1807 - v1816;
        let v1818: f64 = v198 * v1791;
        let v1819: f64 = v143 * v1767;
        let v1820: f64 = v138 * v1757;
        let v1821: f64 = v1819 + v1820;
        let v1822: f64 = v1818 - v1821;
        let v1823: f64 = v125 * v1822;
        let v1824: f64 = v198 * v1778;
        let v1825: f64 = v143 * v1765;
        let v1826: f64 = v167 * v1757;
        let v1827: f64 = v1825 - v1826;
        let v1828: f64 = v1824 - v1827;
        let v1829: f64 = v122 * v1828;
        let v1830: f64 = v1823 + v1829;
        let v1831: f64 = v139 * v1830;
        let v1832: f64 = v1817 - v1831;
        let v1833: f64 = v94 * v1832;
        let v1834: f64 = v1802 + v1833;
        let v1835: f64 = v1801 - v1834;
        let v1836: f64 = v107 * v1753;
        let v1837: f64 = v183 * v1757;
        let v1838: f64 = v1836 + v1837;
        let v1839: f64 = v1838 + v1830;
        let v1840: f64 = v80 * v1839;
        let v1841: f64 = v1835 + v1840;
        let v1842: f64 = v54 * v1841;
        let v1843: f64 = v122 * v1822;
        let v1844: f64 = v125 * v1828;
        let v1845: f64 = v1843 - v1844;
        let v1846: f64 = v224 * v1776;
        let v1847: f64 = v109 * v1757;
        let v1848: f64 = v1846 + v1847;
        let v1849: f64 = v1845 - v1848;
        let v1850: f64 = v91 * v1849;
        let v1851: f64 = v281 * v94;
        let v1852: f64 = v1850 - v1851;
        let v1853: f64 = v288 * v91;
        let v1854: f64 = v109 * v1753;
        let v1855: f64 = v224 * v1762;
        let v1856: f64 = v1854 + v1855;
        let v1857: f64 = v138 * v1765;
        let v1858: f64 = v167 * v1767;
        let v1859: f64 = v1857 + v1858;
        let v1860: f64 = v198 * v1762;
        let v1861: f64 = v1859 + v1860;
        let v1862: f64 = v1856 + v1861;
        let v1863: f64 = v94 * v1862;
        let v1864: f64 = v1853 - v1863;
        let v1865: f64 = v1852 - v1864;
        let v1866: f64 = v80 * v1865;
        let v1867: f64 = v104 * v1753;
        let v1868: f64 = v179 * v1757;
        let v1869: f64 = v1867 - v1868;
        let v1870: f64 = v183 * v1762;
        let v1871: f64 = v107 * v1776;
        let v1872: f64 = v1870 - v1871;
        let v1873: f64 = v1869 - v1872;
        let v1874: f64 = v125 * v1782;
        let v1875: f64 = v122 * v1795;
        let v1876: f64 = v1874 + v1875;
        let v1877: f64 = v1873 + v1876;
        let v1878: f64 = v139 * v1861;
        let v1879: f64 = v1877 - v1878;
        let v1880: f64 = v1866 - v1879;
        let v1881: f64 = v57 * v1880;
        let v1882: f64 = v1842 - v1881;
        let v1883: f64 = v23 * v1882;
        let v1884: f64 = v173 * v91;
        let v1885: f64 = v94 * v1798;
        let v1886: f64 = v1884 + v1885;
        let v1887: f64 = v91 * v1832;
        let v1888: f64 = v213 * v94;
        let v1889: f64 = v1887 - v1888;
        let v1890: f64 = v1886 + v1889;
        let v1891: f64 = v57 * v1865;
        let v1892: f64 = v54 * v1839;
        let v1893: f64 = v1891 - v1892;
        let v1894: f64 = v75 * v1893;
        let v1895: f64 = v1890 + v1894;
        let v1896: f64 = v25 * v1895;
        let v1897: f64 = v1883 - v1896;
        let v1898: f64 = v18 * v1893;
        let v1899: f64 = v1897 - v1898;
        let v1900: f64 = v2 * v1899;
        let v1901: f64 = v54 * v1865;
        let v1902: f64 = v57 * v1839;
        let v1903: f64 = v1901 + v1902;
        let v1904: f64 = v23 * v1903;
        let v1905: f64 = v281 * v91;
        let v1906: f64 = v94 * v1849;
        let v1907: f64 = v1905 + v1906;
        let v1908: f64 = v288 * v94;
        let v1909: f64 = v91 * v1862;
        let v1910: f64 = v1908 + v1909;
        let v1911: f64 = v1907 - v1910;
        let v1912: f64 = v25 * v1911;
        let v1913: f64 = v1904 - v1912;
        let v1914: f64 = v18 * v1913;
        let v1915: f64 = v75 * v1911;
        let v1916: f64 = v57 * v1841;
        let v1917: f64 = v54 * v1880;
        let v1918: f64 = v1916 + v1917;
        let v1919: f64 = v1915 - v1918;
        let v1920: f64 = v25 * v1903;
        let v1921: f64 = v23 * v1911;
        let v1922: f64 = v1920 + v1921;
        let v1923: f64 = v40 * v1922;
        let v1924: f64 = v1919 + v1923;
        let v1925: f64 = v1914 - v1924;
        let v1926: f64 = v4 * v1925;
        let v1927: f64 = v1900 - v1926;
        let v1928: f64 = v6 * v1927;
        let v1929: f64 = v25 * v1882;
        let v1930: f64 = v23 * v1895;
        let v1931: f64 = v1929 + v1930;
        let v1932: f64 = v40 * v1893;
        let v1933: f64 = v1931 + v1932;
        let v1934: f64 = v14 * v1933;
        let v1935: f64 = v1928 - v1934;
        let v1936: f64 = v0 * v1935;
        let v1937: f64 = qd[5];
        let v1938: f64 = v1936 * v1937;
        let v1939: f64 = v1750 + v1938;
        let v1940: f64 = v64 * v122;
        let v1941: f64 = v96 * v125;
        let v1942: f64 = v1940 - v1941;
        let v1943: f64 = v123 * v1942;
        let v1944: f64 = v64 * v125;
        let v1945: f64 = v96 * v122;
        let v1946: f64 = v1944 + v1945;
        let v1947: f64 = v129 * v1946;
        let v1948: f64 = v1943 - v1947;
        let v1949: f64 = v145 * v125;
        let v1950: f64 = v149 * v122;
        let v1951: f64 = v1949 + v1950;
        let v1952: f64 = v143 * v1951;
        let v1953: f64 = v1948 + v1952;
        let v1954: f64 = v122 * v1953;
        let v1955: f64 = v154 * v125;
        let v1956: f64 = v1954 - v1955;
        let v1957: f64 = v170 * v122;
        let v1958: f64 = v129 * v1942;
        let v1959: f64 = v157 * v1946;
        let v1960: f64 = v1958 - v1959;
        let v1961: f64 = v145 * v122;
        let v1962: f64 = v149 * v125;
        let v1963: f64 = v1961 - v1962;
        let v1964: f64 = v143 * v1963;
        let v1965: f64 = v1960 + v1964;
        let v1966: f64 = v125 * v1965;
        let v1967: f64 = v1957 + v1966;
        let v1968: f64 = v1956 - v1967;
        let v1969: f64 = v91 * v1968;
        let v1970: f64 = v135 * v1942;
        let v1971: f64 = v160 * v1946;
        let v1972: f64 = v1970 - v1971;
        let v1973: f64 = v167 * v1951;
        let v1974: f64 = v138 * v1963;
        let v1975: f64 = v1973 + v1974;
        let v1976: f64 = v1972 - v1975;
        let v1977: f64 = v203 * v122;
        let v1978: f64 = v198 * v1963;
        let v1979: f64 = v143 * v1946;
        (
            v1816,
            v1879,
            v1890,
            v1899,
            v1919,
            v1925,
            v1933,
            v1936,
            v1937,
            v1939,
            v1942,
            v1946,
            v1951,
            v1953,
            v1965,
            v1968,
            v1969,
            v1976,
            v1977,
            v1978,
            v1979,
        )
    };
    let (
        v2019,
        v2026,
        v2035,
        v2051,
        v2057,
        v2065,
        v2068,
        v2069,
        v2072,
        v2073,
        v2074,
        v2075,
        v2077,
        v2079,
        v2080,
        v2081,
        v2082,
        v2084,
        v2090,
        v2092,
        v2094,
        v2097,
        v2100,
        v2104,
        v2111,
        v2114,
        v2118,
        v2121,
        v2124,
        v2127,
        v2131,
        v2142,
        v2144,
        v2147,
        v2150,
        v2154,
        v2160,
        v2163,
        v2167,
        v2169,
        v2172,
        v2173,
        v2176,
        v2177,
    ) = {
        let v1980: f64 = v1978 - v1979;
        let v1981: f64 = v125 * v1980;
        let v1982: f64 = v1977 + v1981;
        let v1983: f64 = v209 * v125;
        let v1984: f64 = v198 * v1951;
        let v1985: f64 = v143 * v1942;
        let v1986: f64 = v1984 + v1985;
        let v1987: f64 = v122 * v1986;
        let v1988: f64 = v1983 + v1987;
        let v1989: f64 = v1982 - v1988;
        let v1990: f64 = v139 * v1989;
        let v1991: f64 = v1976 + v1990;
        let v1992: f64 = v94 * v1991;
        let v1993: f64 = v1969 + v1992;
        let v1994: f64 = v80 * v1989;
        let v1995: f64 = v1993 + v1994;
        let v1996: f64 = v54 * v1995;
        let v1997: f64 = v122 * v1980;
        let v1998: f64 = v203 * v125;
        let v1999: f64 = v1997 - v1998;
        let v2000: f64 = v209 * v122;
        let v2001: f64 = v125 * v1986;
        let v2002: f64 = v2000 - v2001;
        let v2003: f64 = v1999 - v2002;
        let v2004: f64 = v91 * v2003;
        let v2005: f64 = v138 * v1942;
        let v2006: f64 = v167 * v1946;
        let v2007: f64 = v2005 + v2006;
        let v2008: f64 = v94 * v2007;
        let v2009: f64 = v2004 + v2008;
        let v2010: f64 = v80 * v2009;
        let v2011: f64 = v154 * v122;
        let v2012: f64 = v125 * v1953;
        let v2013: f64 = v2011 + v2012;
        let v2014: f64 = v122 * v1965;
        let v2015: f64 = v170 * v125;
        let v2016: f64 = v2014 - v2015;
        let v2017: f64 = v2013 + v2016;
        let v2018: f64 = v139 * v2007;
        let v2019: f64 = v2017 - v2018;
        let v2020: f64 = v2010 - v2019;
        let v2021: f64 = v57 * v2020;
        let v2022: f64 = v1996 - v2021;
        let v2023: f64 = v23 * v2022;
        let v2024: f64 = v94 * v1968;
        let v2025: f64 = v91 * v1991;
        let v2026: f64 = v2024 - v2025;
        let v2027: f64 = v57 * v2009;
        let v2028: f64 = v54 * v1989;
        let v2029: f64 = v2027 - v2028;
        let v2030: f64 = v75 * v2029;
        let v2031: f64 = v2026 + v2030;
        let v2032: f64 = v25 * v2031;
        let v2033: f64 = v2023 - v2032;
        let v2034: f64 = v18 * v2029;
        let v2035: f64 = v2033 - v2034;
        let v2036: f64 = v2 * v2035;
        let v2037: f64 = v54 * v2009;
        let v2038: f64 = v57 * v1989;
        let v2039: f64 = v2037 + v2038;
        let v2040: f64 = v23 * v2039;
        let v2041: f64 = v94 * v2003;
        let v2042: f64 = v91 * v2007;
        let v2043: f64 = v2041 - v2042;
        let v2044: f64 = v25 * v2043;
        let v2045: f64 = v2040 - v2044;
        let v2046: f64 = v18 * v2045;
        let v2047: f64 = v75 * v2043;
        let v2048: f64 = v57 * v1995;
        let v2049: f64 = v54 * v2020;
        let v2050: f64 = v2048 + v2049;
        let v2051: f64 = v2047 - v2050;
        let v2052: f64 = v25 * v2039;
        let v2053: f64 = v23 * v2043;
        let v2054: f64 = v2052 + v2053;
        let v2055: f64 = v40 * v2054;
        let v2056: f64 = v2051 + v2055;
        let v2057: f64 = v2046 - v2056;
        let v2058: f64 = v4 * v2057;
        let v2059: f64 = v2036 - v2058;
        let v2060: f64 = v6 * v2059;
        let v2061: f64 = v25 * v2022;
        let v2062: f64 = v23 * v2031;
        let v2063: f64 = v2061 + v2062;
        let v2064: f64 = v40 * v2029;
        let v2065: f64 = v2063 + v2064;
        let v2066: f64 = v14 * v2065;
        let v2067: f64 = v2060 - v2066;
        let v2068: f64 = v0 * v2067;
        let v2069: f64 = qd[6];
        let v2070: f64 = v2068 * v2069;
        let v2071: f64 = v1939 + v2070;
        let v2072: f64 = -v2071;
        let v2073: f64 = qd[0];
        let v2074: f64 = v822 * v2073;
        let v2075: f64 = params[16];
        let v2076: f64 = v9 * v4;
        let v2077: f64 = v3 * v2;
        let v2078: f64 = v2076 + v2077;
        let v2079: f64 = v18 * v4;
        let v2080: f64 = v17 * v2079;
        let v2081: f64 = v2078 + v2080;
        let v2082: f64 = v23 * v4;
        let v2083: f64 = v24 * v2082;
        let v2084: f64 = v25 * v4;
        let v2085: f64 = v30 * v2084;
        let v2086: f64 = v2083 - v2085;
        let v2087: f64 = v36 * v2;
        let v2088: f64 = v2086 - v2087;
        let v2089: f64 = v39 * v2079;
        let v2090: f64 = v40 * v2;
        let v2091: f64 = v23 * v2090;
        let v2092: f64 = v18 * v2;
        let v2093: f64 = v25 * v2092;
        let v2094: f64 = v2091 + v2093;
        let v2095: f64 = v44 * v2094;
        let v2096: f64 = v2089 + v2095;
        let v2097: f64 = v2088 + v2096;
        let v2098: f64 = v54 * v2082;
        let v2099: f64 = v57 * v2;
        let v2100: f64 = v2098 + v2099;
        let v2101: f64 = v55 * v2100;
        let v2102: f64 = v57 * v2082;
        let v2103: f64 = v54 * v2;
        let v2104: f64 = v2102 - v2103;
        let v2105: f64 = v61 * v2104;
        let v2106: f64 = v2101 - v2105;
        let v2107: f64 = v67 * v2084;
        let v2108: f64 = v2106 - v2107;
        let v2109: f64 = v23 * v2092;
        let v2110: f64 = v25 * v2090;
        let v2111: f64 = v2109 - v2110;
        let v2112: f64 = v57 * v2111;
        let v2113: f64 = v75 * v2084;
        let v2114: f64 = v2113 + v2079;
        let v2115: f64 = v54 * v2114;
        let v2116: f64 = v2112 + v2115;
        let v2117: f64 = v80 * v2100;
        let v2118: f64 = v2116 + v2117;
        let v2119: f64 = v70 * v2118;
        let v2120: f64 = v75 * v2;
        let v2121: f64 = v2094 + v2120;
        let v2122: f64 = v84 * v2121;
        let v2123: f64 = v2119 - v2122;
        let v2124: f64 = v2108 + v2123;
        let v2125: f64 = v91 * v2100;
        let v2126: f64 = v94 * v2084;
        let v2127: f64 = v2125 - v2126;
        let v2128: f64 = v92 * v2127;
        let v2129: f64 = v91 * v2084;
        let v2130: f64 = v94 * v2100;
        let v2131: f64 = v2129 + v2130;
        let v2132: f64 = v98 * v2131;
        let v2133: f64 = v2128 - v2132;
        let v2134: f64 = v104 * v2104;
        let v2135: f64 = v2133 + v2134;
        let v2136: f64 = v107 * v2118;
        let v2137: f64 = v91 * v2121;
        let v2138: f64 = v54 * v2111;
        let v2139: f64 = v57 * v2114;
        let v2140: f64 = v2138 - v2139;
        let v2141: f64 = v80 * v2104;
        let v2142: f64 = v2140 - v2141;
        let v2143: f64 = v94 * v2142;
        let v2144: f64 = v2137 + v2143;
        let v2145: f64 = v109 * v2144;
        let v2146: f64 = v2136 + v2145;
        let v2147: f64 = v2135 + v2146;
        let v2148: f64 = v122 * v2127;
        let v2149: f64 = v125 * v2104;
        let v2150: f64 = v2148 + v2149;
        let v2151: f64 = v123 * v2150;
        let v2152: f64 = v122 * v2104;
        let v2153: f64 = v125 * v2127;
        let v2154: f64 = v2152 - v2153;
        let v2155: f64 = v129 * v2154;
        let v2156: f64 = v2151 + v2155;
        let v2157: f64 = v135 * v2131;
        let v2158: f64 = v2156 + v2157;
        let v2159: f64 = v139 * v2104;
        let v2160: f64 = v2159 - v2144;
        let v2161: f64 = v138 * v2160;
        let v2162: f64 = v139 * v2131;
        let v2163: f64 = v2118 + v2162;
        let v2164: f64 = v122 * v2163;
        let v2165: f64 = v91 * v2142;
        let v2166: f64 = v94 * v2121;
        let v2167: f64 = v2165 - v2166;
        let v2168: f64 = v125 * v2167;
        let v2169: f64 = v2164 - v2168;
        let v2170: f64 = v143 * v2169;
        let v2171: f64 = v2161 + v2170;
        let v2172: f64 = v2158 - v2171;
        let v2173: f64 = v122 * v2172;
        let v2174: f64 = v129 * v2150;
        let v2175: f64 = v157 * v2154;
        let v2176: f64 = v2174 + v2175;
        let v2177: f64 = v160 * v2131;
        (
            v2019,
            v2026,
            v2035,
            v2051,
            v2057,
            v2065,
            v2068,
            v2069,
            v2072,
            v2073,
            v2074,
            v2075,
            v2077,
            v2079,
            v2080,
            v2081,
            v2082,
            v2084,
            v2090,
            v2092,
            v2094,
            v2097,
            v2100,
            v2104,
            v2111,
            v2114,
            v2118,
            v2121,
            v2124,
            v2127,
            v2131,
            v2142,
            v2144,
            v2147,
            v2150,
            v2154,
            v2160,
            v2163,
            v2167,
            v2169,
            v2172,
            v2173,
            v2176,
            v2177,
        )
    };
    let (
        v2185,
        v2188,
        v2213,
        v2219,
        v2223,
        v2238,
        v2240,
        v2285,
        v2292,
        v2295,
        v2297,
        v2300,
        v2329,
        v2335,
        v2341,
        v2344,
        v2345,
        v2346,
        v2349,
        v2372,
        v2375,
    ) = {
        let v2178: f64 = v2176 + v2177;
        let v2179: f64 = v122 * v2167;
        let v2180: f64 = v125 * v2163;
        let v2181: f64 = v2179 + v2180;
        let v2182: f64 = v143 * v2181;
        let v2183: f64 = v167 * v2160;
        let v2184: f64 = v2182 + v2183;
        let v2185: f64 = v2178 + v2184;
        let v2186: f64 = v125 * v2185;
        let v2187: f64 = v2173 - v2186;
        let v2188: f64 = v2147 + v2187;
        let v2189: f64 = v91 * v2188;
        let v2190: f64 = v98 * v2127;
        let v2191: f64 = v176 * v2131;
        let v2192: f64 = v2190 - v2191;
        let v2193: f64 = v179 * v2104;
        let v2194: f64 = v2192 + v2193;
        let v2195: f64 = v109 * v2167;
        let v2196: f64 = v183 * v2118;
        let v2197: f64 = v2195 - v2196;
        let v2198: f64 = v2194 + v2197;
        let v2199: f64 = v135 * v2150;
        let v2200: f64 = v160 * v2154;
        let v2201: f64 = v2199 + v2200;
        let v2202: f64 = v190 * v2131;
        let v2203: f64 = v2201 + v2202;
        let v2204: f64 = v167 * v2169;
        let v2205: f64 = v138 * v2181;
        let v2206: f64 = v2204 - v2205;
        let v2207: f64 = v2203 + v2206;
        let v2208: f64 = v2198 - v2207;
        let v2209: f64 = v198 * v2181;
        let v2210: f64 = v143 * v2154;
        let v2211: f64 = v138 * v2131;
        let v2212: f64 = v2210 - v2211;
        let v2213: f64 = v2209 + v2212;
        let v2214: f64 = v125 * v2213;
        let v2215: f64 = v198 * v2169;
        let v2216: f64 = v167 * v2131;
        let v2217: f64 = v143 * v2150;
        let v2218: f64 = v2216 - v2217;
        let v2219: f64 = v2215 + v2218;
        let v2220: f64 = v122 * v2219;
        let v2221: f64 = v2214 + v2220;
        let v2222: f64 = v139 * v2221;
        let v2223: f64 = v2208 - v2222;
        let v2224: f64 = v94 * v2223;
        let v2225: f64 = v2189 - v2224;
        let v2226: f64 = v2124 + v2225;
        let v2227: f64 = v217 * v2084;
        let v2228: f64 = v70 * v2100;
        let v2229: f64 = v2227 + v2228;
        let v2230: f64 = v221 * v2118;
        let v2231: f64 = v2229 + v2230;
        let v2232: f64 = v224 * v2118;
        let v2233: f64 = v107 * v2127;
        let v2234: f64 = v183 * v2131;
        let v2235: f64 = v2233 + v2234;
        let v2236: f64 = v2232 + v2235;
        let v2237: f64 = v2236 + v2221;
        let v2238: f64 = v2231 + v2237;
        let v2239: f64 = v80 * v2238;
        let v2240: f64 = v2226 + v2239;
        let v2241: f64 = v54 * v2240;
        let v2242: f64 = v61 * v2100;
        let v2243: f64 = v236 * v2104;
        let v2244: f64 = v2242 - v2243;
        let v2245: f64 = v239 * v2084;
        let v2246: f64 = v2244 - v2245;
        let v2247: f64 = v70 * v2142;
        let v2248: f64 = v217 * v2121;
        let v2249: f64 = v2247 + v2248;
        let v2250: f64 = v2246 + v2249;
        let v2251: f64 = v104 * v2127;
        let v2252: f64 = v179 * v2131;
        let v2253: f64 = v2251 - v2252;
        let v2254: f64 = v249 * v2104;
        let v2255: f64 = v2253 + v2254;
        let v2256: f64 = v183 * v2144;
        let v2257: f64 = v107 * v2167;
        let v2258: f64 = v2256 + v2257;
        let v2259: f64 = v2255 - v2258;
        let v2260: f64 = v125 * v2172;
        let v2261: f64 = v122 * v2185;
        let v2262: f64 = v2260 + v2261;
        let v2263: f64 = v2259 + v2262;
        let v2264: f64 = v138 * v2150;
        let v2265: f64 = v167 * v2154;
        let v2266: f64 = v2264 - v2265;
        let v2267: f64 = v198 * v2160;
        let v2268: f64 = v2266 - v2267;
        let v2269: f64 = v139 * v2268;
        let v2270: f64 = v2263 - v2269;
        let v2271: f64 = v2250 - v2270;
        let v2272: f64 = v221 * v2142;
        let v2273: f64 = v70 * v2104;
        let v2274: f64 = v84 * v2084;
        let v2275: f64 = v2273 - v2274;
        let v2276: f64 = v2272 - v2275;
        let v2277: f64 = v224 * v2167;
        let v2278: f64 = v109 * v2131;
        let v2279: f64 = v107 * v2104;
        let v2280: f64 = v2278 + v2279;
        let v2281: f64 = v2277 - v2280;
        let v2282: f64 = v122 * v2213;
        let v2283: f64 = v125 * v2219;
        let v2284: f64 = v2282 - v2283;
        let v2285: f64 = v2281 + v2284;
        let v2286: f64 = v91 * v2285;
        let v2287: f64 = v183 * v2104;
        let v2288: f64 = v109 * v2127;
        let v2289: f64 = v2287 - v2288;
        let v2290: f64 = v224 * v2144;
        let v2291: f64 = v2289 - v2290;
        let v2292: f64 = v2291 - v2268;
        let v2293: f64 = v94 * v2292;
        let v2294: f64 = v2286 - v2293;
        let v2295: f64 = v2276 + v2294;
        let v2296: f64 = v80 * v2295;
        let v2297: f64 = v2271 + v2296;
        let v2298: f64 = v57 * v2297;
        let v2299: f64 = v2241 - v2298;
        let v2300: f64 = v2097 + v2299;
        let v2301: f64 = v23 * v2300;
        let v2302: f64 = v30 * v2082;
        let v2303: f64 = v299 * v2084;
        let v2304: f64 = v2302 - v2303;
        let v2305: f64 = v302 * v2;
        let v2306: f64 = v2304 - v2305;
        let v2307: f64 = v44 * v2111;
        let v2308: f64 = v306 * v2079;
        let v2309: f64 = v2307 - v2308;
        let v2310: f64 = v2306 + v2309;
        let v2311: f64 = v67 * v2100;
        let v2312: f64 = v239 * v2104;
        let v2313: f64 = v2311 - v2312;
        let v2314: f64 = v313 * v2084;
        let v2315: f64 = v2313 - v2314;
        let v2316: f64 = v217 * v2118;
        let v2317: f64 = v84 * v2142;
        let v2318: f64 = v2316 + v2317;
        let v2319: f64 = v2315 - v2318;
        let v2320: f64 = v94 * v2188;
        let v2321: f64 = v91 * v2223;
        let v2322: f64 = v2320 + v2321;
        let v2323: f64 = v2319 + v2322;
        let v2324: f64 = v2310 + v2323;
        let v2325: f64 = v57 * v2295;
        let v2326: f64 = v54 * v2238;
        let v2327: f64 = v2325 - v2326;
        let v2328: f64 = v75 * v2327;
        let v2329: f64 = v2324 + v2328;
        let v2330: f64 = v25 * v2329;
        let v2331: f64 = v2301 - v2330;
        let v2332: f64 = v2081 + v2331;
        let v2333: f64 = v333 * v2079;
        let v2334: f64 = v17 * v4;
        let v2335: f64 = v2333 + v2334;
        let v2336: f64 = v39 * v2082;
        let v2337: f64 = v306 * v2084;
        let v2338: f64 = v2336 + v2337;
        let v2339: f64 = v343 * v2079;
        let v2340: f64 = v2338 + v2339;
        let v2341: f64 = v2340 - v2327;
        let v2342: f64 = v2335 + v2341;
        let v2343: f64 = v18 * v2342;
        let v2344: f64 = v2332 + v2343;
        let v2345: f64 = v2 * v2344;
        let v2346: f64 = v3 * v4;
        let v2347: f64 = v351 * v2;
        let v2348: f64 = v2346 + v2347;
        let v2349: f64 = v17 * v2092;
        let v2350: f64 = v2348 + v2349;
        let v2351: f64 = v36 * v2082;
        let v2352: f64 = v302 * v2084;
        let v2353: f64 = v2351 - v2352;
        let v2354: f64 = v363 * v2;
        let v2355: f64 = v2353 - v2354;
        let v2356: f64 = v306 * v2094;
        let v2357: f64 = v39 * v2111;
        let v2358: f64 = v2356 + v2357;
        let v2359: f64 = v2355 - v2358;
        let v2360: f64 = v57 * v2240;
        let v2361: f64 = v54 * v2297;
        let v2362: f64 = v2360 + v2361;
        let v2363: f64 = v2359 - v2362;
        let v2364: f64 = v84 * v2100;
        let v2365: f64 = v217 * v2104;
        let v2366: f64 = v2364 + v2365;
        let v2367: f64 = v221 * v2121;
        let v2368: f64 = v2366 - v2367;
        let v2369: f64 = v94 * v2285;
        let v2370: f64 = v91 * v2292;
        let v2371: f64 = v2369 + v2370;
        let v2372: f64 = v2368 + v2371;
        let v2373: f64 = v75 * v2372;
        let v2374: f64 = v2363 + v2373;
        let v2375: f64 = v2350 - v2374;
        (
            v2185,
            v2188,
            v2213,
            v2219,
            v2223,
            v2238,
            v2240,
            v2285,
            v2292,
            v2295,
            v2297,
            v2300,
            v2329,
            v2335,
            v2341,
            v2344,
            v2345,
            v2346,
            v2349,
            v2372,
            v2375,
        )
    };
    let (
        v2384,
        v2391,
        v2398,
        v2404,
        v2409,
        v2425,
        v2429,
        v2432,
        v2433,
        v2435,
        v2444,
        v2447,
        v2450,
        v2454,
        v2461,
        v2468,
        v2471,
        v2474,
        v2477,
        v2481,
        v2491,
        v2494,
        v2500,
        v2504,
        v2510,
        v2517,
        v2522,
        v2535,
        v2538,
        v2539,
        v2557,
        v2563,
        v2569,
        v2571,
        v2573,
    ) = {
        let v2376: f64 = v343 * v2111;
        let v2377: f64 = v39 * v2;
        let v2378: f64 = v44 * v2084;
        let v2379: f64 = v2377 - v2378;
        let v2380: f64 = v2376 + v2379;
        let v2381: f64 = v54 * v2295;
        let v2382: f64 = v57 * v2238;
        let v2383: f64 = v2381 + v2382;
        let v2384: f64 = v2380 + v2383;
        let v2385: f64 = v25 * v2384;
        let v2386: f64 = v343 * v2094;
        let v2387: f64 = v306 * v2;
        let v2388: f64 = v44 * v2082;
        let v2389: f64 = v2387 + v2388;
        let v2390: f64 = v2386 + v2389;
        let v2391: f64 = v2372 - v2390;
        let v2392: f64 = v23 * v2391;
        let v2393: f64 = v2385 + v2392;
        let v2394: f64 = v40 * v2393;
        let v2395: f64 = v2375 - v2394;
        let v2396: f64 = v333 * v2092;
        let v2397: f64 = v17 * v2;
        let v2398: f64 = v2396 + v2397;
        let v2399: f64 = v23 * v2384;
        let v2400: f64 = v25 * v2391;
        let v2401: f64 = v2399 - v2400;
        let v2402: f64 = v2398 + v2401;
        let v2403: f64 = v18 * v2402;
        let v2404: f64 = v2395 + v2403;
        let v2405: f64 = v4 * v2404;
        let v2406: f64 = v2345 - v2405;
        let v2407: f64 = v2075 + v2406;
        let v2408: f64 = v2407 * v14;
        let v2409: f64 = params[18];
        let v2410: f64 = v13 * v4;
        let v2411: f64 = v355 * v2;
        let v2412: f64 = v2410 + v2411;
        let v2413: f64 = v335 * v2079;
        let v2414: f64 = v408 * v2092;
        let v2415: f64 = v2413 + v2414;
        let v2416: f64 = v2412 - v2415;
        let v2417: f64 = v25 * v2300;
        let v2418: f64 = v23 * v2329;
        let v2419: f64 = v2417 + v2418;
        let v2420: f64 = v2416 + v2419;
        let v2421: f64 = v40 * v2341;
        let v2422: f64 = v2420 - v2421;
        let v2423: f64 = v2409 - v2422;
        let v2424: f64 = v2423 * v6;
        let v2425: f64 = v2408 - v2424;
        let v2426: f64 = v2425 + v2425;
        let v2427: f64 = v0 * v2426;
        let v2428: f64 = v2427 * v823;
        let v2429: f64 = v2074 + v2428;
        let v2430: f64 = v9 * v2;
        let v2431: f64 = v2430 - v2346;
        let v2432: f64 = v2431 + v2349;
        let v2433: f64 = v23 * v2;
        let v2434: f64 = v24 * v2433;
        let v2435: f64 = v25 * v2;
        let v2436: f64 = v30 * v2435;
        let v2437: f64 = v2434 - v2436;
        let v2438: f64 = v36 * v4;
        let v2439: f64 = v2437 + v2438;
        let v2440: f64 = v39 * v2092;
        let v2441: f64 = v40 * v4;
        let v2442: f64 = v23 * v2441;
        let v2443: f64 = v25 * v2079;
        let v2444: f64 = v2442 + v2443;
        let v2445: f64 = v44 * v2444;
        let v2446: f64 = v2440 - v2445;
        let v2447: f64 = v2439 + v2446;
        let v2448: f64 = v54 * v2433;
        let v2449: f64 = v57 * v4;
        let v2450: f64 = v2448 - v2449;
        let v2451: f64 = v55 * v2450;
        let v2452: f64 = v57 * v2433;
        let v2453: f64 = v54 * v4;
        let v2454: f64 = v2452 + v2453;
        let v2455: f64 = v61 * v2454;
        let v2456: f64 = v2451 - v2455;
        let v2457: f64 = v67 * v2435;
        let v2458: f64 = v2456 - v2457;
        let v2459: f64 = v25 * v2441;
        let v2460: f64 = v23 * v2079;
        let v2461: f64 = v2459 - v2460;
        let v2462: f64 = v57 * v2461;
        let v2463: f64 = v75 * v2435;
        let v2464: f64 = v2463 + v2092;
        let v2465: f64 = v54 * v2464;
        let v2466: f64 = v2462 + v2465;
        let v2467: f64 = v80 * v2450;
        let v2468: f64 = v2466 + v2467;
        let v2469: f64 = v70 * v2468;
        let v2470: f64 = v75 * v4;
        let v2471: f64 = v2444 + v2470;
        let v2472: f64 = v84 * v2471;
        let v2473: f64 = v2469 + v2472;
        let v2474: f64 = v2458 + v2473;
        let v2475: f64 = v91 * v2450;
        let v2476: f64 = v94 * v2435;
        let v2477: f64 = v2475 - v2476;
        let v2478: f64 = v92 * v2477;
        let v2479: f64 = v91 * v2435;
        let v2480: f64 = v94 * v2450;
        let v2481: f64 = v2479 + v2480;
        let v2482: f64 = v98 * v2481;
        let v2483: f64 = v2478 - v2482;
        let v2484: f64 = v104 * v2454;
        let v2485: f64 = v2483 + v2484;
        let v2486: f64 = v107 * v2468;
        let v2487: f64 = v54 * v2461;
        let v2488: f64 = v57 * v2464;
        let v2489: f64 = v2487 - v2488;
        let v2490: f64 = v80 * v2454;
        let v2491: f64 = v2489 - v2490;
        let v2492: f64 = v94 * v2491;
        let v2493: f64 = v91 * v2471;
        let v2494: f64 = v2492 - v2493;
        let v2495: f64 = v109 * v2494;
        let v2496: f64 = v2486 + v2495;
        let v2497: f64 = v2485 + v2496;
        let v2498: f64 = v122 * v2477;
        let v2499: f64 = v125 * v2454;
        let v2500: f64 = v2498 + v2499;
        let v2501: f64 = v123 * v2500;
        let v2502: f64 = v122 * v2454;
        let v2503: f64 = v125 * v2477;
        let v2504: f64 = v2502 - v2503;
        let v2505: f64 = v129 * v2504;
        let v2506: f64 = v2501 + v2505;
        let v2507: f64 = v135 * v2481;
        let v2508: f64 = v2506 + v2507;
        let v2509: f64 = v139 * v2454;
        let v2510: f64 = v2509 - v2494;
        let v2511: f64 = v138 * v2510;
        let v2512: f64 = v139 * v2481;
        let v2513: f64 = v2468 + v2512;
        let v2514: f64 = v122 * v2513;
        let v2515: f64 = v91 * v2491;
        let v2516: f64 = v94 * v2471;
        let v2517: f64 = v2515 + v2516;
        let v2518: f64 = v125 * v2517;
        let v2519: f64 = v2514 - v2518;
        let v2520: f64 = v143 * v2519;
        let v2521: f64 = v2511 + v2520;
        let v2522: f64 = v2508 - v2521;
        let v2523: f64 = v122 * v2522;
        let v2524: f64 = v129 * v2500;
        let v2525: f64 = v157 * v2504;
        let v2526: f64 = v2524 + v2525;
        let v2527: f64 = v160 * v2481;
        let v2528: f64 = v2526 + v2527;
        let v2529: f64 = v122 * v2517;
        let v2530: f64 = v125 * v2513;
        let v2531: f64 = v2529 + v2530;
        let v2532: f64 = v143 * v2531;
        let v2533: f64 = v167 * v2510;
        let v2534: f64 = v2532 + v2533;
        let v2535: f64 = v2528 + v2534;
        let v2536: f64 = v125 * v2535;
        let v2537: f64 = v2523 - v2536;
        let v2538: f64 = v2497 + v2537;
        let v2539: f64 = v91 * v2538;
        let v2540: f64 = v98 * v2477;
        let v2541: f64 = v176 * v2481;
        let v2542: f64 = v2540 - v2541;
        let v2543: f64 = v179 * v2454;
        let v2544: f64 = v2542 + v2543;
        let v2545: f64 = v109 * v2517;
        let v2546: f64 = v183 * v2468;
        let v2547: f64 = v2545 - v2546;
        let v2548: f64 = v2544 + v2547;
        let v2549: f64 = v135 * v2500;
        let v2550: f64 = v160 * v2504;
        let v2551: f64 = v2549 + v2550;
        let v2552: f64 = v190 * v2481;
        let v2553: f64 = v2551 + v2552;
        let v2554: f64 = v167 * v2519;
        let v2555: f64 = v138 * v2531;
        let v2556: f64 = v2554 - v2555;
        let v2557: f64 = v2553 + v2556;
        let v2558: f64 = v2548 - v2557;
        let v2559: f64 = v198 * v2531;
        let v2560: f64 = v143 * v2504;
        let v2561: f64 = v138 * v2481;
        let v2562: f64 = v2560 - v2561;
        let v2563: f64 = v2559 + v2562;
        let v2564: f64 = v125 * v2563;
        let v2565: f64 = v198 * v2519;
        let v2566: f64 = v167 * v2481;
        let v2567: f64 = v143 * v2500;
        let v2568: f64 = v2566 - v2567;
        let v2569: f64 = v2565 + v2568;
        let v2570: f64 = v122 * v2569;
        let v2571: f64 = v2564 + v2570;
        let v2572: f64 = v139 * v2571;
        let v2573: f64 = v2558 - v2572;
        (
            v2384,
            v2391,
            v2398,
            v2404,
            v2409,
            v2425,
            v2429,
            v2432,
            v2433,
            v2435,
            v2444,
            v2447,
            v2450,
            v2454,
            v2461,
            v2468,
            v2471,
            v2474,
            v2477,
            v2481,
            v2491,
            v2494,
            v2500,
            v2504,
            v2510,
            v2517,
            v2522,
            v2535,
            v2538,
            v2539,
            v2557,
            v2563,
            v2569,
            v2571,
            v2573,
        )
    };
    let (v2620, v2673, v2691, v2722, v2749, v2766, v2768, v2770, v2771) = {
        let v2574: f64 = v94 * v2573;
        let v2575: f64 = v2539 - v2574;
        let v2576: f64 = v2474 + v2575;
        let v2577: f64 = v217 * v2435;
        let v2578: f64 = v70 * v2450;
        let v2579: f64 = v2577 + v2578;
        let v2580: f64 = v221 * v2468;
        let v2581: f64 = v2579 + v2580;
        let v2582: f64 = v224 * v2468;
        let v2583: f64 = v107 * v2477;
        let v2584: f64 = v183 * v2481;
        let v2585: f64 = v2583 + v2584;
        let v2586: f64 = v2582 + v2585;
        let v2587: f64 = v2586 + v2571;
        let v2588: f64 = v2581 + v2587;
        let v2589: f64 = v80 * v2588;
        let v2590: f64 = v2576 + v2589;
        let v2591: f64 = v54 * v2590;
        let v2592: f64 = v61 * v2450;
        let v2593: f64 = v236 * v2454;
        let v2594: f64 = v2592 - v2593;
        let v2595: f64 = v239 * v2435;
        let v2596: f64 = v2594 - v2595;
        let v2597: f64 = v70 * v2491;
        let v2598: f64 = v217 * v2471;
        let v2599: f64 = v2597 - v2598;
        let v2600: f64 = v2596 + v2599;
        let v2601: f64 = v104 * v2477;
        let v2602: f64 = v179 * v2481;
        let v2603: f64 = v2601 - v2602;
        let v2604: f64 = v249 * v2454;
        let v2605: f64 = v2603 + v2604;
        let v2606: f64 = v183 * v2494;
        let v2607: f64 = v107 * v2517;
        let v2608: f64 = v2606 + v2607;
        let v2609: f64 = v2605 - v2608;
        let v2610: f64 = v125 * v2522;
        let v2611: f64 = v122 * v2535;
        let v2612: f64 = v2610 + v2611;
        let v2613: f64 = v2609 + v2612;
        let v2614: f64 = v138 * v2500;
        let v2615: f64 = v167 * v2504;
        let v2616: f64 = v2614 - v2615;
        let v2617: f64 = v198 * v2510;
        let v2618: f64 = v2616 - v2617;
        let v2619: f64 = v139 * v2618;
        let v2620: f64 = v2613 - v2619;
        let v2621: f64 = v2600 - v2620;
        let v2622: f64 = v221 * v2491;
        let v2623: f64 = v70 * v2454;
        let v2624: f64 = v84 * v2435;
        let v2625: f64 = v2623 - v2624;
        let v2626: f64 = v2622 - v2625;
        let v2627: f64 = v224 * v2517;
        let v2628: f64 = v109 * v2481;
        let v2629: f64 = v107 * v2454;
        let v2630: f64 = v2628 + v2629;
        let v2631: f64 = v2627 - v2630;
        let v2632: f64 = v122 * v2563;
        let v2633: f64 = v125 * v2569;
        let v2634: f64 = v2632 - v2633;
        let v2635: f64 = v2631 + v2634;
        let v2636: f64 = v91 * v2635;
        let v2637: f64 = v183 * v2454;
        let v2638: f64 = v109 * v2477;
        let v2639: f64 = v2637 - v2638;
        let v2640: f64 = v224 * v2494;
        let v2641: f64 = v2639 - v2640;
        let v2642: f64 = v2641 - v2618;
        let v2643: f64 = v94 * v2642;
        let v2644: f64 = v2636 - v2643;
        let v2645: f64 = v2626 + v2644;
        let v2646: f64 = v80 * v2645;
        let v2647: f64 = v2621 + v2646;
        let v2648: f64 = v57 * v2647;
        let v2649: f64 = v2591 - v2648;
        let v2650: f64 = v2447 + v2649;
        let v2651: f64 = v23 * v2650;
        let v2652: f64 = v30 * v2433;
        let v2653: f64 = v299 * v2435;
        let v2654: f64 = v2652 - v2653;
        let v2655: f64 = v302 * v4;
        let v2656: f64 = v2654 + v2655;
        let v2657: f64 = v44 * v2461;
        let v2658: f64 = v306 * v2092;
        let v2659: f64 = v2657 - v2658;
        let v2660: f64 = v2656 + v2659;
        let v2661: f64 = v67 * v2450;
        let v2662: f64 = v239 * v2454;
        let v2663: f64 = v2661 - v2662;
        let v2664: f64 = v313 * v2435;
        let v2665: f64 = v2663 - v2664;
        let v2666: f64 = v217 * v2468;
        let v2667: f64 = v84 * v2491;
        let v2668: f64 = v2666 + v2667;
        let v2669: f64 = v2665 - v2668;
        let v2670: f64 = v94 * v2538;
        let v2671: f64 = v91 * v2573;
        let v2672: f64 = v2670 + v2671;
        let v2673: f64 = v2669 + v2672;
        let v2674: f64 = v2660 + v2673;
        let v2675: f64 = v57 * v2645;
        let v2676: f64 = v54 * v2588;
        let v2677: f64 = v2675 - v2676;
        let v2678: f64 = v75 * v2677;
        let v2679: f64 = v2674 + v2678;
        let v2680: f64 = v25 * v2679;
        let v2681: f64 = v2651 - v2680;
        let v2682: f64 = v2432 + v2681;
        let v2683: f64 = v39 * v2433;
        let v2684: f64 = v306 * v2435;
        let v2685: f64 = v2683 + v2684;
        let v2686: f64 = v343 * v2092;
        let v2687: f64 = v2685 + v2686;
        let v2688: f64 = v2687 - v2677;
        let v2689: f64 = v2398 + v2688;
        let v2690: f64 = v18 * v2689;
        let v2691: f64 = v2682 + v2690;
        let v2692: f64 = v2 * v2691;
        let v2693: f64 = v2344 * v4;
        let v2694: f64 = v2692 - v2693;
        let v2695: f64 = v2404 * v2;
        let v2696: f64 = v351 * v4;
        let v2697: f64 = v2077 - v2696;
        let v2698: f64 = v2697 - v2080;
        let v2699: f64 = v36 * v2433;
        let v2700: f64 = v302 * v2435;
        let v2701: f64 = v2699 - v2700;
        let v2702: f64 = v363 * v4;
        let v2703: f64 = v2701 + v2702;
        let v2704: f64 = v39 * v2461;
        let v2705: f64 = v306 * v2444;
        let v2706: f64 = v2704 - v2705;
        let v2707: f64 = v2703 - v2706;
        let v2708: f64 = v57 * v2590;
        let v2709: f64 = v54 * v2647;
        let v2710: f64 = v2708 + v2709;
        let v2711: f64 = v2707 - v2710;
        let v2712: f64 = v84 * v2450;
        let v2713: f64 = v217 * v2454;
        let v2714: f64 = v2712 + v2713;
        let v2715: f64 = v221 * v2471;
        let v2716: f64 = v2714 + v2715;
        let v2717: f64 = v94 * v2635;
        let v2718: f64 = v91 * v2642;
        let v2719: f64 = v2717 + v2718;
        let v2720: f64 = v2716 + v2719;
        let v2721: f64 = v75 * v2720;
        let v2722: f64 = v2711 + v2721;
        let v2723: f64 = v2698 - v2722;
        let v2724: f64 = v343 * v2461;
        let v2725: f64 = v39 * v4;
        let v2726: f64 = v44 * v2435;
        let v2727: f64 = v2725 + v2726;
        let v2728: f64 = v2724 - v2727;
        let v2729: f64 = v54 * v2645;
        let v2730: f64 = v57 * v2588;
        let v2731: f64 = v2729 + v2730;
        let v2732: f64 = v2728 + v2731;
        let v2733: f64 = v25 * v2732;
        let v2734: f64 = v44 * v2433;
        let v2735: f64 = v306 * v4;
        let v2736: f64 = v2734 - v2735;
        let v2737: f64 = v343 * v2444;
        let v2738: f64 = v2736 - v2737;
        let v2739: f64 = v2720 - v2738;
        let v2740: f64 = v23 * v2739;
        let v2741: f64 = v2733 + v2740;
        let v2742: f64 = v40 * v2741;
        let v2743: f64 = v2723 - v2742;
        let v2744: f64 = v23 * v2732;
        let v2745: f64 = v25 * v2739;
        let v2746: f64 = v2744 - v2745;
        let v2747: f64 = v2746 - v2335;
        let v2748: f64 = v18 * v2747;
        let v2749: f64 = v2743 + v2748;
        let v2750: f64 = v4 * v2749;
        let v2751: f64 = v2695 + v2750;
        let v2752: f64 = v2694 - v2751;
        let v2753: f64 = v6 * v2752;
        let v2754: f64 = v13 * v2;
        let v2755: f64 = v355 * v4;
        let v2756: f64 = v2754 - v2755;
        let v2757: f64 = v335 * v2092;
        let v2758: f64 = v408 * v2079;
        let v2759: f64 = v2757 - v2758;
        let v2760: f64 = v2756 - v2759;
        let v2761: f64 = v25 * v2650;
        let v2762: f64 = v23 * v2679;
        let v2763: f64 = v2761 + v2762;
        let v2764: f64 = v2760 + v2763;
        let v2765: f64 = v40 * v2688;
        let v2766: f64 = v2764 - v2765;
        let v2767: f64 = v14 * v2766;
        let v2768: f64 = v2753 - v2767;
        let v2769: f64 = v24 * v25;
        let v2770: f64 = v30 * v23;
        let v2771: f64 = v2769 + v2770;
        (v2620, v2673, v2691, v2722, v2749, v2766, v2768, v2770, v2771)
    };
    let (
        v2774,
        v2776,
        v2782,
        v2790,
        v2802,
        v2822,
        v2824,
        v2829,
        v2842,
        v2845,
        v2870,
        v2876,
        v2880,
        v2895,
        v2897,
        v2935,
        v2942,
        v2950,
        v2952,
        v2955,
        v2956,
        v2957,
        v2961,
        v2966,
        v2969,
    ) = {
        let v2772: f64 = v40 * v39;
        let v2773: f64 = v2771 - v2772;
        let v2774: f64 = v54 * v25;
        let v2775: f64 = v55 * v2774;
        let v2776: f64 = v57 * v25;
        let v2777: f64 = v61 * v2776;
        let v2778: f64 = v2775 - v2777;
        let v2779: f64 = v67 * v23;
        let v2780: f64 = v2778 + v2779;
        let v2781: f64 = v75 * v23;
        let v2782: f64 = v75 - v2781;
        let v2783: f64 = v54 * v2782;
        let v2784: f64 = v80 * v2774;
        let v2785: f64 = v2783 + v2784;
        let v2786: f64 = v70 * v2785;
        let v2787: f64 = v2780 + v2786;
        let v2788: f64 = v91 * v2774;
        let v2789: f64 = v94 * v23;
        let v2790: f64 = v2788 + v2789;
        let v2791: f64 = v92 * v2790;
        let v2792: f64 = v91 * v23;
        let v2793: f64 = v94 * v2774;
        let v2794: f64 = v2792 - v2793;
        let v2795: f64 = v98 * v2794;
        let v2796: f64 = v2791 + v2795;
        let v2797: f64 = v104 * v2776;
        let v2798: f64 = v2796 + v2797;
        let v2799: f64 = v107 * v2785;
        let v2800: f64 = v57 * v2782;
        let v2801: f64 = v80 * v2776;
        let v2802: f64 = v2800 + v2801;
        let v2803: f64 = v94 * v2802;
        let v2804: f64 = v109 * v2803;
        let v2805: f64 = v2799 - v2804;
        let v2806: f64 = v2798 + v2805;
        let v2807: f64 = v122 * v2790;
        let v2808: f64 = v125 * v2776;
        let v2809: f64 = v2807 + v2808;
        let v2810: f64 = v123 * v2809;
        let v2811: f64 = v122 * v2776;
        let v2812: f64 = v125 * v2790;
        let v2813: f64 = v2811 - v2812;
        let v2814: f64 = v129 * v2813;
        let v2815: f64 = v2810 + v2814;
        let v2816: f64 = v135 * v2794;
        let v2817: f64 = v2815 - v2816;
        let v2818: f64 = v139 * v2776;
        let v2819: f64 = v2803 + v2818;
        let v2820: f64 = v138 * v2819;
        let v2821: f64 = v139 * v2794;
        let v2822: f64 = v2785 - v2821;
        let v2823: f64 = v122 * v2822;
        let v2824: f64 = v91 * v2802;
        let v2825: f64 = v125 * v2824;
        let v2826: f64 = v2823 + v2825;
        let v2827: f64 = v143 * v2826;
        let v2828: f64 = v2820 + v2827;
        let v2829: f64 = v2817 - v2828;
        let v2830: f64 = v122 * v2829;
        let v2831: f64 = v129 * v2809;
        let v2832: f64 = v157 * v2813;
        let v2833: f64 = v2831 + v2832;
        let v2834: f64 = v160 * v2794;
        let v2835: f64 = v2833 - v2834;
        let v2836: f64 = v125 * v2822;
        let v2837: f64 = v122 * v2824;
        let v2838: f64 = v2836 - v2837;
        let v2839: f64 = v143 * v2838;
        let v2840: f64 = v167 * v2819;
        let v2841: f64 = v2839 + v2840;
        let v2842: f64 = v2835 + v2841;
        let v2843: f64 = v125 * v2842;
        let v2844: f64 = v2830 - v2843;
        let v2845: f64 = v2806 + v2844;
        let v2846: f64 = v91 * v2845;
        let v2847: f64 = v98 * v2790;
        let v2848: f64 = v176 * v2794;
        let v2849: f64 = v2847 + v2848;
        let v2850: f64 = v179 * v2776;
        let v2851: f64 = v2849 + v2850;
        let v2852: f64 = v109 * v2824;
        let v2853: f64 = v183 * v2785;
        let v2854: f64 = v2852 + v2853;
        let v2855: f64 = v2851 - v2854;
        let v2856: f64 = v135 * v2809;
        let v2857: f64 = v160 * v2813;
        let v2858: f64 = v2856 + v2857;
        let v2859: f64 = v190 * v2794;
        let v2860: f64 = v2858 - v2859;
        let v2861: f64 = v167 * v2826;
        let v2862: f64 = v138 * v2838;
        let v2863: f64 = v2861 - v2862;
        let v2864: f64 = v2860 + v2863;
        let v2865: f64 = v2855 - v2864;
        let v2866: f64 = v198 * v2838;
        let v2867: f64 = v143 * v2813;
        let v2868: f64 = v138 * v2794;
        let v2869: f64 = v2867 + v2868;
        let v2870: f64 = v2866 + v2869;
        let v2871: f64 = v125 * v2870;
        let v2872: f64 = v198 * v2826;
        let v2873: f64 = v167 * v2794;
        let v2874: f64 = v143 * v2809;
        let v2875: f64 = v2873 + v2874;
        let v2876: f64 = v2872 - v2875;
        let v2877: f64 = v122 * v2876;
        let v2878: f64 = v2871 + v2877;
        let v2879: f64 = v139 * v2878;
        let v2880: f64 = v2865 - v2879;
        let v2881: f64 = v94 * v2880;
        let v2882: f64 = v2846 - v2881;
        let v2883: f64 = v2787 + v2882;
        let v2884: f64 = v217 * v23;
        let v2885: f64 = v70 * v2774;
        let v2886: f64 = v2884 - v2885;
        let v2887: f64 = v221 * v2785;
        let v2888: f64 = v2886 - v2887;
        let v2889: f64 = v224 * v2785;
        let v2890: f64 = v107 * v2790;
        let v2891: f64 = v183 * v2794;
        let v2892: f64 = v2890 - v2891;
        let v2893: f64 = v2889 + v2892;
        let v2894: f64 = v2893 + v2878;
        let v2895: f64 = v2888 - v2894;
        let v2896: f64 = v80 * v2895;
        let v2897: f64 = v2883 - v2896;
        let v2898: f64 = v54 * v2897;
        let v2899: f64 = v61 * v2774;
        let v2900: f64 = v236 * v2776;
        let v2901: f64 = v2899 - v2900;
        let v2902: f64 = v239 * v23;
        let v2903: f64 = v2901 + v2902;
        let v2904: f64 = v70 * v2802;
        let v2905: f64 = v2903 - v2904;
        let v2906: f64 = v104 * v2790;
        let v2907: f64 = v179 * v2794;
        let v2908: f64 = v2906 + v2907;
        let v2909: f64 = v249 * v2776;
        let v2910: f64 = v2908 + v2909;
        let v2911: f64 = v183 * v2803;
        let v2912: f64 = v107 * v2824;
        let v2913: f64 = v2911 + v2912;
        let v2914: f64 = v2910 + v2913;
        let v2915: f64 = v125 * v2829;
        let v2916: f64 = v122 * v2842;
        let v2917: f64 = v2915 + v2916;
        let v2918: f64 = v2914 + v2917;
        let v2919: f64 = v138 * v2809;
        let v2920: f64 = v167 * v2813;
        let v2921: f64 = v2919 - v2920;
        let v2922: f64 = v198 * v2819;
        let v2923: f64 = v2921 - v2922;
        let v2924: f64 = v139 * v2923;
        let v2925: f64 = v2918 - v2924;
        let v2926: f64 = v2905 - v2925;
        let v2927: f64 = v109 * v2794;
        let v2928: f64 = v107 * v2776;
        let v2929: f64 = v2927 - v2928;
        let v2930: f64 = v224 * v2824;
        let v2931: f64 = v2929 - v2930;
        let v2932: f64 = v122 * v2870;
        let v2933: f64 = v125 * v2876;
        let v2934: f64 = v2932 - v2933;
        let v2935: f64 = v2931 + v2934;
        let v2936: f64 = v91 * v2935;
        let v2937: f64 = v224 * v2803;
        let v2938: f64 = v183 * v2776;
        let v2939: f64 = v109 * v2790;
        let v2940: f64 = v2938 - v2939;
        let v2941: f64 = v2937 + v2940;
        let v2942: f64 = v2941 - v2923;
        let v2943: f64 = v94 * v2942;
        let v2944: f64 = v2936 - v2943;
        let v2945: f64 = v221 * v2802;
        let v2946: f64 = v70 * v2776;
        let v2947: f64 = v84 * v23;
        let v2948: f64 = v2946 + v2947;
        let v2949: f64 = v2945 + v2948;
        let v2950: f64 = v2944 - v2949;
        let v2951: f64 = v80 * v2950;
        let v2952: f64 = v2926 + v2951;
        let v2953: f64 = v57 * v2952;
        let v2954: f64 = v2898 - v2953;
        let v2955: f64 = v2773 + v2954;
        let v2956: f64 = v23 * v2955;
        let v2957: f64 = v30 * v25;
        let v2958: f64 = v299 * v23;
        let v2959: f64 = v2957 + v2958;
        let v2960: f64 = v40 * v306;
        let v2961: f64 = v2959 + v2960;
        let v2962: f64 = v67 * v2774;
        let v2963: f64 = v239 * v2776;
        let v2964: f64 = v2962 - v2963;
        let v2965: f64 = v313 * v23;
        let v2966: f64 = v2964 + v2965;
        let v2967: f64 = v217 * v2785;
        let v2968: f64 = v84 * v2802;
        let v2969: f64 = v2967 - v2968;
        (
            v2774,
            v2776,
            v2782,
            v2790,
            v2802,
            v2822,
            v2824,
            v2829,
            v2842,
            v2845,
            v2870,
            v2876,
            v2880,
            v2895,
            v2897,
            v2935,
            v2942,
            v2950,
            v2952,
            v2955,
            v2956,
            v2957,
            v2961,
            v2966,
            v2969,
        )
    };
    let (
        v2980,
        v2992,
        v3011,
        v3015,
        v3017,
        v3018,
        v3028,
        v3039,
        v3043,
        v3046,
        v3048,
        v3050,
        v3053,
        v3054,
        v3056,
        v3065,
        v3069,
        v3073,
        v3080,
        v3082,
        v3087,
        v3091,
        v3099,
        v3103,
        v3113,
        v3118,
        v3121,
        v3134,
        v3137,
        v3138,
        v3156,
        v3157,
        v3162,
        v3163,
        v3164,
        v3167,
    ) = {
        let v2970: f64 = v2966 - v2969;
        let v2971: f64 = v94 * v2845;
        let v2972: f64 = v91 * v2880;
        let v2973: f64 = v2971 + v2972;
        let v2974: f64 = v2970 + v2973;
        let v2975: f64 = v2961 + v2974;
        let v2976: f64 = v57 * v2950;
        let v2977: f64 = v54 * v2895;
        let v2978: f64 = v2976 + v2977;
        let v2979: f64 = v75 * v2978;
        let v2980: f64 = v2975 + v2979;
        let v2981: f64 = v25 * v2980;
        let v2982: f64 = v2956 - v2981;
        let v2983: f64 = v13 + v2982;
        let v2984: f64 = v39 * v25;
        let v2985: f64 = v306 * v23;
        let v2986: f64 = v2984 - v2985;
        let v2987: f64 = v40 * v343;
        let v2988: f64 = v2986 - v2987;
        let v2989: f64 = v2988 - v2978;
        let v2990: f64 = v335 - v2989;
        let v2991: f64 = v18 * v2990;
        let v2992: f64 = v2983 - v2991;
        let v2993: f64 = v2 * v2992;
        let v2994: f64 = v36 * v25;
        let v2995: f64 = v302 * v23;
        let v2996: f64 = v2994 + v2995;
        let v2997: f64 = v57 * v2897;
        let v2998: f64 = v54 * v2952;
        let v2999: f64 = v2997 + v2998;
        let v3000: f64 = v2996 - v2999;
        let v3001: f64 = v84 * v2774;
        let v3002: f64 = v217 * v2776;
        let v3003: f64 = v3001 + v3002;
        let v3004: f64 = v94 * v2935;
        let v3005: f64 = v91 * v2942;
        let v3006: f64 = v3004 + v3005;
        let v3007: f64 = v3003 + v3006;
        let v3008: f64 = v75 * v3007;
        let v3009: f64 = v3000 + v3008;
        let v3010: f64 = v355 - v3009;
        let v3011: f64 = v44 * v23;
        let v3012: f64 = v54 * v2950;
        let v3013: f64 = v57 * v2895;
        let v3014: f64 = v3012 - v3013;
        let v3015: f64 = v3011 + v3014;
        let v3016: f64 = v25 * v3015;
        let v3017: f64 = v44 * v25;
        let v3018: f64 = v3007 - v3017;
        let v3019: f64 = v23 * v3018;
        let v3020: f64 = v3016 + v3019;
        let v3021: f64 = v40 * v3020;
        let v3022: f64 = v3010 - v3021;
        let v3023: f64 = v23 * v3015;
        let v3024: f64 = v25 * v3018;
        let v3025: f64 = v3023 - v3024;
        let v3026: f64 = v3025 - v408;
        let v3027: f64 = v18 * v3026;
        let v3028: f64 = v3022 + v3027;
        let v3029: f64 = v4 * v3028;
        let v3030: f64 = v2993 - v3029;
        let v3031: f64 = v3030 * v14;
        let v3032: f64 = v25 * v2955;
        let v3033: f64 = v23 * v2980;
        let v3034: f64 = v3032 + v3033;
        let v3035: f64 = v786 + v3034;
        let v3036: f64 = v40 * v2989;
        let v3037: f64 = v3035 - v3036;
        let v3038: f64 = v3037 * v6;
        let v3039: f64 = v3031 + v3038;
        let v3040: f64 = v2768 + v3039;
        let v3041: f64 = v0 * v3040;
        let v3042: f64 = v3041 * v1179;
        let v3043: f64 = v2429 + v3042;
        let v3044: f64 = v2092 * v23;
        let v3045: f64 = v2090 * v25;
        let v3046: f64 = v3044 - v3045;
        let v3047: f64 = v44 * v3046;
        let v3048: f64 = v4 * v25;
        let v3049: f64 = v24 * v3048;
        let v3050: f64 = v4 * v23;
        let v3051: f64 = v30 * v3050;
        let v3052: f64 = v3049 + v3051;
        let v3053: f64 = v3047 - v3052;
        let v3054: f64 = v57 * v3048;
        let v3055: f64 = v61 * v3054;
        let v3056: f64 = v54 * v3048;
        let v3057: f64 = v55 * v3056;
        let v3058: f64 = v3055 - v3057;
        let v3059: f64 = v67 * v3050;
        let v3060: f64 = v3058 - v3059;
        let v3061: f64 = v75 * v3050;
        let v3062: f64 = v54 * v3061;
        let v3063: f64 = v2092 * v25;
        let v3064: f64 = v2090 * v23;
        let v3065: f64 = v3063 + v3064;
        let v3066: f64 = v57 * v3065;
        let v3067: f64 = v3062 - v3066;
        let v3068: f64 = v80 * v3056;
        let v3069: f64 = v3067 - v3068;
        let v3070: f64 = v70 * v3069;
        let v3071: f64 = v84 * v3046;
        let v3072: f64 = v3070 - v3071;
        let v3073: f64 = v3060 + v3072;
        let v3074: f64 = v107 * v3069;
        let v3075: f64 = v91 * v3046;
        let v3076: f64 = v80 * v3054;
        let v3077: f64 = v54 * v3065;
        let v3078: f64 = v57 * v3061;
        let v3079: f64 = v3077 + v3078;
        let v3080: f64 = v3076 - v3079;
        let v3081: f64 = v94 * v3080;
        let v3082: f64 = v3075 + v3081;
        let v3083: f64 = v109 * v3082;
        let v3084: f64 = v3074 + v3083;
        let v3085: f64 = v91 * v3056;
        let v3086: f64 = v94 * v3050;
        let v3087: f64 = v3085 + v3086;
        let v3088: f64 = v92 * v3087;
        let v3089: f64 = v91 * v3050;
        let v3090: f64 = v94 * v3056;
        let v3091: f64 = v3089 - v3090;
        let v3092: f64 = v98 * v3091;
        let v3093: f64 = v3088 + v3092;
        let v3094: f64 = v104 * v3054;
        let v3095: f64 = v3093 + v3094;
        let v3096: f64 = v3084 - v3095;
        let v3097: f64 = v125 * v3087;
        let v3098: f64 = v122 * v3054;
        let v3099: f64 = v3097 - v3098;
        let v3100: f64 = v129 * v3099;
        let v3101: f64 = v122 * v3087;
        let v3102: f64 = v125 * v3054;
        let v3103: f64 = v3101 + v3102;
        let v3104: f64 = v123 * v3103;
        let v3105: f64 = v3100 - v3104;
        let v3106: f64 = v135 * v3091;
        let v3107: f64 = v3105 + v3106;
        let v3108: f64 = v139 * v3091;
        let v3109: f64 = v3069 + v3108;
        let v3110: f64 = v122 * v3109;
        let v3111: f64 = v91 * v3080;
        let v3112: f64 = v94 * v3046;
        let v3113: f64 = v3111 - v3112;
        let v3114: f64 = v125 * v3113;
        let v3115: f64 = v3110 - v3114;
        let v3116: f64 = v143 * v3115;
        let v3117: f64 = v139 * v3054;
        let v3118: f64 = v3117 + v3082;
        let v3119: f64 = v138 * v3118;
        let v3120: f64 = v3116 - v3119;
        let v3121: f64 = v3107 - v3120;
        let v3122: f64 = v122 * v3121;
        let v3123: f64 = v157 * v3099;
        let v3124: f64 = v129 * v3103;
        let v3125: f64 = v3123 - v3124;
        let v3126: f64 = v160 * v3091;
        let v3127: f64 = v3125 + v3126;
        let v3128: f64 = v122 * v3113;
        let v3129: f64 = v125 * v3109;
        let v3130: f64 = v3128 + v3129;
        let v3131: f64 = v143 * v3130;
        let v3132: f64 = v167 * v3118;
        let v3133: f64 = v3131 - v3132;
        let v3134: f64 = v3127 + v3133;
        let v3135: f64 = v125 * v3134;
        let v3136: f64 = v3122 - v3135;
        let v3137: f64 = v3096 + v3136;
        let v3138: f64 = v91 * v3137;
        let v3139: f64 = v109 * v3113;
        let v3140: f64 = v183 * v3069;
        let v3141: f64 = v3139 - v3140;
        let v3142: f64 = v98 * v3087;
        let v3143: f64 = v176 * v3091;
        let v3144: f64 = v3142 + v3143;
        let v3145: f64 = v179 * v3054;
        let v3146: f64 = v3144 + v3145;
        let v3147: f64 = v3141 - v3146;
        let v3148: f64 = v160 * v3099;
        let v3149: f64 = v135 * v3103;
        let v3150: f64 = v3148 - v3149;
        let v3151: f64 = v190 * v3091;
        let v3152: f64 = v3150 + v3151;
        let v3153: f64 = v167 * v3115;
        let v3154: f64 = v138 * v3130;
        let v3155: f64 = v3153 - v3154;
        let v3156: f64 = v3152 + v3155;
        let v3157: f64 = v3147 - v3156;
        let v3158: f64 = v198 * v3130;
        let v3159: f64 = v143 * v3099;
        let v3160: f64 = v138 * v3091;
        let v3161: f64 = v3159 - v3160;
        let v3162: f64 = v3158 + v3161;
        let v3163: f64 = v125 * v3162;
        let v3164: f64 = v198 * v3115;
        let v3165: f64 = v167 * v3091;
        let v3166: f64 = v143 * v3103;
        let v3167: f64 = v3165 + v3166;
        (
            v2980,
            v2992,
            v3011,
            v3015,
            v3017,
            v3018,
            v3028,
            v3039,
            v3043,
            v3046,
            v3048,
            v3050,
            v3053,
            v3054,
            v3056,
            v3065,
            v3069,
            v3073,
            v3080,
            v3082,
            v3087,
            v3091,
            v3099,
            v3103,
            v3113,
            v3118,
            v3121,
            v3134,
            v3137,
            v3138,
            v3156,
            v3157,
            v3162,
            v3163,
            v3164,
            v3167,
        )
    };
    let (
        v3219,
        v3266,
        v3286,
        v3328,
        v3338,
        v3350,
        v3352,
        v3354,
        v3355,
        v3358,
        v3360,
        v3361,
        v3363,
        v3365,
    ) = {
        let v3168: f64 = v3164 + v3167;
        let v3169: f64 = v122 * v3168;
        let v3170: f64 = v3163 + v3169;
        let v3171: f64 = v139 * v3170;
        let v3172: f64 = v3157 - v3171;
        let v3173: f64 = v94 * v3172;
        let v3174: f64 = v3138 - v3173;
        let v3175: f64 = v3073 + v3174;
        let v3176: f64 = v217 * v3050;
        let v3177: f64 = v70 * v3056;
        let v3178: f64 = v3176 - v3177;
        let v3179: f64 = v221 * v3069;
        let v3180: f64 = v3178 + v3179;
        let v3181: f64 = v224 * v3069;
        let v3182: f64 = v183 * v3091;
        let v3183: f64 = v107 * v3087;
        let v3184: f64 = v3182 - v3183;
        let v3185: f64 = v3181 + v3184;
        let v3186: f64 = v3185 + v3170;
        let v3187: f64 = v3180 + v3186;
        let v3188: f64 = v80 * v3187;
        let v3189: f64 = v3175 + v3188;
        let v3190: f64 = v54 * v3189;
        let v3191: f64 = v236 * v3054;
        let v3192: f64 = v61 * v3056;
        let v3193: f64 = v3191 - v3192;
        let v3194: f64 = v239 * v3050;
        let v3195: f64 = v3193 - v3194;
        let v3196: f64 = v70 * v3080;
        let v3197: f64 = v217 * v3046;
        let v3198: f64 = v3196 + v3197;
        let v3199: f64 = v3195 + v3198;
        let v3200: f64 = v125 * v3121;
        let v3201: f64 = v122 * v3134;
        let v3202: f64 = v3200 + v3201;
        let v3203: f64 = v104 * v3087;
        let v3204: f64 = v179 * v3091;
        let v3205: f64 = v3203 + v3204;
        let v3206: f64 = v249 * v3054;
        let v3207: f64 = v3205 + v3206;
        let v3208: f64 = v183 * v3082;
        let v3209: f64 = v107 * v3113;
        let v3210: f64 = v3208 + v3209;
        let v3211: f64 = v3207 + v3210;
        let v3212: f64 = v3202 - v3211;
        let v3213: f64 = v198 * v3118;
        let v3214: f64 = v138 * v3103;
        let v3215: f64 = v167 * v3099;
        let v3216: f64 = v3214 + v3215;
        let v3217: f64 = v3213 - v3216;
        let v3218: f64 = v139 * v3217;
        let v3219: f64 = v3212 - v3218;
        let v3220: f64 = v3199 - v3219;
        let v3221: f64 = v221 * v3080;
        let v3222: f64 = v70 * v3054;
        let v3223: f64 = v84 * v3050;
        let v3224: f64 = v3222 + v3223;
        let v3225: f64 = v3221 + v3224;
        let v3226: f64 = v224 * v3113;
        let v3227: f64 = v109 * v3091;
        let v3228: f64 = v107 * v3054;
        let v3229: f64 = v3227 - v3228;
        let v3230: f64 = v3226 - v3229;
        let v3231: f64 = v122 * v3162;
        let v3232: f64 = v125 * v3168;
        let v3233: f64 = v3231 - v3232;
        let v3234: f64 = v3230 + v3233;
        let v3235: f64 = v91 * v3234;
        let v3236: f64 = v109 * v3087;
        let v3237: f64 = v183 * v3054;
        let v3238: f64 = v3236 - v3237;
        let v3239: f64 = v224 * v3082;
        let v3240: f64 = v3238 - v3239;
        let v3241: f64 = v3240 - v3217;
        let v3242: f64 = v94 * v3241;
        let v3243: f64 = v3235 - v3242;
        let v3244: f64 = v3225 + v3243;
        let v3245: f64 = v80 * v3244;
        let v3246: f64 = v3220 + v3245;
        let v3247: f64 = v57 * v3246;
        let v3248: f64 = v3190 - v3247;
        let v3249: f64 = v3053 + v3248;
        let v3250: f64 = v23 * v3249;
        let v3251: f64 = v2300 * v25;
        let v3252: f64 = v3250 - v3251;
        let v3253: f64 = v2329 * v23;
        let v3254: f64 = v239 * v3054;
        let v3255: f64 = v67 * v3056;
        let v3256: f64 = v3254 - v3255;
        let v3257: f64 = v313 * v3050;
        let v3258: f64 = v3256 - v3257;
        let v3259: f64 = v217 * v3069;
        let v3260: f64 = v84 * v3080;
        let v3261: f64 = v3259 + v3260;
        let v3262: f64 = v3258 - v3261;
        let v3263: f64 = v94 * v3137;
        let v3264: f64 = v91 * v3172;
        let v3265: f64 = v3263 + v3264;
        let v3266: f64 = v3262 + v3265;
        let v3267: f64 = v30 * v3048;
        let v3268: f64 = v299 * v3050;
        let v3269: f64 = v3267 + v3268;
        let v3270: f64 = v44 * v3065;
        let v3271: f64 = v3269 + v3270;
        let v3272: f64 = v3266 - v3271;
        let v3273: f64 = v57 * v3244;
        let v3274: f64 = v54 * v3187;
        let v3275: f64 = v3273 - v3274;
        let v3276: f64 = v75 * v3275;
        let v3277: f64 = v3272 + v3276;
        let v3278: f64 = v25 * v3277;
        let v3279: f64 = v3253 + v3278;
        let v3280: f64 = v3252 - v3279;
        let v3281: f64 = v306 * v3050;
        let v3282: f64 = v39 * v3048;
        let v3283: f64 = v3281 - v3282;
        let v3284: f64 = v3283 - v3275;
        let v3285: f64 = v18 * v3284;
        let v3286: f64 = v3280 + v3285;
        let v3287: f64 = v2 * v3286;
        let v3288: f64 = v54 * v3244;
        let v3289: f64 = v57 * v3187;
        let v3290: f64 = v3288 + v3289;
        let v3291: f64 = v343 * v3065;
        let v3292: f64 = v44 * v3050;
        let v3293: f64 = v3291 + v3292;
        let v3294: f64 = v3290 - v3293;
        let v3295: f64 = v23 * v3294;
        let v3296: f64 = v2384 * v25;
        let v3297: f64 = v3295 - v3296;
        let v3298: f64 = v2391 * v23;
        let v3299: f64 = v94 * v3234;
        let v3300: f64 = v91 * v3241;
        let v3301: f64 = v3299 + v3300;
        let v3302: f64 = v84 * v3056;
        let v3303: f64 = v217 * v3054;
        let v3304: f64 = v3302 + v3303;
        let v3305: f64 = v221 * v3046;
        let v3306: f64 = v3304 + v3305;
        let v3307: f64 = v3301 - v3306;
        let v3308: f64 = v343 * v3046;
        let v3309: f64 = v44 * v3048;
        let v3310: f64 = v3308 - v3309;
        let v3311: f64 = v3307 - v3310;
        let v3312: f64 = v25 * v3311;
        let v3313: f64 = v3298 + v3312;
        let v3314: f64 = v3297 - v3313;
        let v3315: f64 = v18 * v3314;
        let v3316: f64 = v75 * v3307;
        let v3317: f64 = v36 * v3048;
        let v3318: f64 = v302 * v3050;
        let v3319: f64 = v3317 + v3318;
        let v3320: f64 = v306 * v3046;
        let v3321: f64 = v39 * v3065;
        let v3322: f64 = v3320 - v3321;
        let v3323: f64 = v3319 + v3322;
        let v3324: f64 = v57 * v3189;
        let v3325: f64 = v54 * v3246;
        let v3326: f64 = v3324 + v3325;
        let v3327: f64 = v3323 + v3326;
        let v3328: f64 = v3316 - v3327;
        let v3329: f64 = v2384 * v23;
        let v3330: f64 = v25 * v3294;
        let v3331: f64 = v3329 + v3330;
        let v3332: f64 = v23 * v3311;
        let v3333: f64 = v2391 * v25;
        let v3334: f64 = v3332 - v3333;
        let v3335: f64 = v3331 + v3334;
        let v3336: f64 = v40 * v3335;
        let v3337: f64 = v3328 + v3336;
        let v3338: f64 = v3315 - v3337;
        let v3339: f64 = v4 * v3338;
        let v3340: f64 = v3287 - v3339;
        let v3341: f64 = v6 * v3340;
        let v3342: f64 = v2300 * v23;
        let v3343: f64 = v25 * v3249;
        let v3344: f64 = v3342 + v3343;
        let v3345: f64 = v23 * v3277;
        let v3346: f64 = v2329 * v25;
        let v3347: f64 = v3345 - v3346;
        let v3348: f64 = v3344 + v3347;
        let v3349: f64 = v40 * v3284;
        let v3350: f64 = v3348 - v3349;
        let v3351: f64 = v14 * v3350;
        let v3352: f64 = v3341 - v3351;
        let v3353: f64 = v75 * v84;
        let v3354: f64 = v80 * v57;
        let v3355: f64 = v70 * v3354;
        let v3356: f64 = v3353 - v3355;
        let v3357: f64 = v55 * v57;
        let v3358: f64 = v61 * v54;
        let v3359: f64 = v3357 + v3358;
        let v3360: f64 = v3356 - v3359;
        let v3361: f64 = v94 * v57;
        let v3362: f64 = v98 * v3361;
        let v3363: f64 = v91 * v57;
        let v3364: f64 = v92 * v3363;
        let v3365: f64 = v3362 - v3364;
        (
            v3219,
            v3266,
            v3286,
            v3328,
            v3338,
            v3350,
            v3352,
            v3354,
            v3355,
            v3358,
            v3360,
            v3361,
            v3363,
            v3365,
        )
    };
    let (
        v3369,
        v3370,
        v3391,
        v3393,
        v3395,
        v3400,
        v3413,
        v3416,
        v3441,
        v3447,
        v3451,
        v3455,
        v3456,
        v3464,
        v3466,
        v3476,
        v3488,
        v3491,
        v3492,
        v3494,
        v3496,
        v3499,
        v3519,
        v3522,
        v3538,
        v3540,
        v3544,
        v3545,
        v3549,
        v3559,
        v3560,
        v3563,
    ) = {
        let v3366: f64 = v104 * v54;
        let v3367: f64 = v3365 + v3366;
        let v3368: f64 = v107 * v3354;
        let v3369: f64 = v75 * v91;
        let v3370: f64 = v80 * v54;
        let v3371: f64 = v94 * v3370;
        let v3372: f64 = v3369 + v3371;
        let v3373: f64 = v109 * v3372;
        let v3374: f64 = v3368 + v3373;
        let v3375: f64 = v3367 - v3374;
        let v3376: f64 = v125 * v54;
        let v3377: f64 = v122 * v3363;
        let v3378: f64 = v3376 - v3377;
        let v3379: f64 = v123 * v3378;
        let v3380: f64 = v122 * v54;
        let v3381: f64 = v125 * v3363;
        let v3382: f64 = v3380 + v3381;
        let v3383: f64 = v129 * v3382;
        let v3384: f64 = v3379 + v3383;
        let v3385: f64 = v135 * v3361;
        let v3386: f64 = v3384 - v3385;
        let v3387: f64 = v139 * v54;
        let v3388: f64 = v3372 + v3387;
        let v3389: f64 = v138 * v3388;
        let v3390: f64 = v139 * v3361;
        let v3391: f64 = v3354 + v3390;
        let v3392: f64 = v122 * v3391;
        let v3393: f64 = v75 * v94;
        let v3394: f64 = v91 * v3370;
        let v3395: f64 = v3393 - v3394;
        let v3396: f64 = v125 * v3395;
        let v3397: f64 = v3392 + v3396;
        let v3398: f64 = v143 * v3397;
        let v3399: f64 = v3389 - v3398;
        let v3400: f64 = v3386 - v3399;
        let v3401: f64 = v122 * v3400;
        let v3402: f64 = v129 * v3378;
        let v3403: f64 = v157 * v3382;
        let v3404: f64 = v3402 + v3403;
        let v3405: f64 = v160 * v3361;
        let v3406: f64 = v3404 - v3405;
        let v3407: f64 = v122 * v3395;
        let v3408: f64 = v125 * v3391;
        let v3409: f64 = v3407 - v3408;
        let v3410: f64 = v143 * v3409;
        let v3411: f64 = v167 * v3388;
        let v3412: f64 = v3410 + v3411;
        let v3413: f64 = v3406 + v3412;
        let v3414: f64 = v125 * v3413;
        let v3415: f64 = v3401 - v3414;
        let v3416: f64 = v3375 + v3415;
        let v3417: f64 = v91 * v3416;
        let v3418: f64 = v176 * v3361;
        let v3419: f64 = v98 * v3363;
        let v3420: f64 = v3418 - v3419;
        let v3421: f64 = v179 * v54;
        let v3422: f64 = v3420 + v3421;
        let v3423: f64 = v109 * v3395;
        let v3424: f64 = v183 * v3354;
        let v3425: f64 = v3423 + v3424;
        let v3426: f64 = v3422 + v3425;
        let v3427: f64 = v135 * v3378;
        let v3428: f64 = v160 * v3382;
        let v3429: f64 = v3427 + v3428;
        let v3430: f64 = v190 * v3361;
        let v3431: f64 = v3429 - v3430;
        let v3432: f64 = v167 * v3397;
        let v3433: f64 = v138 * v3409;
        let v3434: f64 = v3432 + v3433;
        let v3435: f64 = v3431 - v3434;
        let v3436: f64 = v3426 - v3435;
        let v3437: f64 = v198 * v3409;
        let v3438: f64 = v143 * v3382;
        let v3439: f64 = v138 * v3361;
        let v3440: f64 = v3438 + v3439;
        let v3441: f64 = v3437 + v3440;
        let v3442: f64 = v125 * v3441;
        let v3443: f64 = v198 * v3397;
        let v3444: f64 = v167 * v3361;
        let v3445: f64 = v143 * v3378;
        let v3446: f64 = v3444 + v3445;
        let v3447: f64 = v3443 + v3446;
        let v3448: f64 = v122 * v3447;
        let v3449: f64 = v3442 - v3448;
        let v3450: f64 = v139 * v3449;
        let v3451: f64 = v3436 - v3450;
        let v3452: f64 = v94 * v3451;
        let v3453: f64 = v3417 - v3452;
        let v3454: f64 = v3360 + v3453;
        let v3455: f64 = v70 * v57;
        let v3456: f64 = v221 * v3354;
        let v3457: f64 = v3455 + v3456;
        let v3458: f64 = v224 * v3354;
        let v3459: f64 = v107 * v3363;
        let v3460: f64 = v183 * v3361;
        let v3461: f64 = v3459 + v3460;
        let v3462: f64 = v3458 + v3461;
        let v3463: f64 = v3449 - v3462;
        let v3464: f64 = v3457 - v3463;
        let v3465: f64 = v80 * v3464;
        let v3466: f64 = v3454 - v3465;
        let v3467: f64 = v54 * v3466;
        let v3468: f64 = v224 * v3395;
        let v3469: f64 = v109 * v3361;
        let v3470: f64 = v107 * v54;
        let v3471: f64 = v3469 - v3470;
        let v3472: f64 = v3468 + v3471;
        let v3473: f64 = v122 * v3441;
        let v3474: f64 = v125 * v3447;
        let v3475: f64 = v3473 + v3474;
        let v3476: f64 = v3472 + v3475;
        let v3477: f64 = v91 * v3476;
        let v3478: f64 = v224 * v3372;
        let v3479: f64 = v183 * v54;
        let v3480: f64 = v109 * v3363;
        let v3481: f64 = v3479 + v3480;
        let v3482: f64 = v3478 + v3481;
        let v3483: f64 = v138 * v3378;
        let v3484: f64 = v167 * v3382;
        let v3485: f64 = v3483 - v3484;
        let v3486: f64 = v198 * v3388;
        let v3487: f64 = v3485 - v3486;
        let v3488: f64 = v3482 - v3487;
        let v3489: f64 = v94 * v3488;
        let v3490: f64 = v3477 - v3489;
        let v3491: f64 = v221 * v3370;
        let v3492: f64 = v70 * v54;
        let v3493: f64 = v3491 + v3492;
        let v3494: f64 = v3490 - v3493;
        let v3495: f64 = v80 * v3494;
        let v3496: f64 = v61 * v57;
        let v3497: f64 = v236 * v54;
        let v3498: f64 = v3496 + v3497;
        let v3499: f64 = v70 * v3370;
        let v3500: f64 = v75 * v217;
        let v3501: f64 = v3499 + v3500;
        let v3502: f64 = v3498 + v3501;
        let v3503: f64 = v179 * v3361;
        let v3504: f64 = v104 * v3363;
        let v3505: f64 = v3503 - v3504;
        let v3506: f64 = v249 * v54;
        let v3507: f64 = v3505 + v3506;
        let v3508: f64 = v183 * v3372;
        let v3509: f64 = v107 * v3395;
        let v3510: f64 = v3508 - v3509;
        let v3511: f64 = v3507 + v3510;
        let v3512: f64 = v125 * v3400;
        let v3513: f64 = v122 * v3413;
        let v3514: f64 = v3512 + v3513;
        let v3515: f64 = v3511 + v3514;
        let v3516: f64 = v139 * v3487;
        let v3517: f64 = v3515 - v3516;
        let v3518: f64 = v3502 + v3517;
        let v3519: f64 = v3495 - v3518;
        let v3520: f64 = v57 * v3519;
        let v3521: f64 = v3467 - v3520;
        let v3522: f64 = v36 + v3521;
        let v3523: f64 = v23 * v3522;
        let v3524: f64 = v217 * v3354;
        let v3525: f64 = v84 * v3370;
        let v3526: f64 = v3524 + v3525;
        let v3527: f64 = v67 * v57;
        let v3528: f64 = v239 * v54;
        let v3529: f64 = v3527 + v3528;
        let v3530: f64 = v3526 - v3529;
        let v3531: f64 = v94 * v3416;
        let v3532: f64 = v91 * v3451;
        let v3533: f64 = v3531 + v3532;
        let v3534: f64 = v3530 + v3533;
        let v3535: f64 = v302 + v3534;
        let v3536: f64 = v57 * v3494;
        let v3537: f64 = v54 * v3464;
        let v3538: f64 = v3536 + v3537;
        let v3539: f64 = v75 * v3538;
        let v3540: f64 = v3535 + v3539;
        let v3541: f64 = v25 * v3540;
        let v3542: f64 = v3523 - v3541;
        let v3543: f64 = v18 * v3538;
        let v3544: f64 = v3542 - v3543;
        let v3545: f64 = v2 * v3544;
        let v3546: f64 = v54 * v3494;
        let v3547: f64 = v57 * v3464;
        let v3548: f64 = v3546 - v3547;
        let v3549: f64 = v3548 - v39;
        let v3550: f64 = v23 * v3549;
        let v3551: f64 = v75 * v221;
        let v3552: f64 = v217 * v54;
        let v3553: f64 = v84 * v57;
        let v3554: f64 = v3552 - v3553;
        let v3555: f64 = v3551 + v3554;
        let v3556: f64 = v94 * v3476;
        let v3557: f64 = v91 * v3488;
        let v3558: f64 = v3556 + v3557;
        let v3559: f64 = v3555 + v3558;
        let v3560: f64 = v306 + v3559;
        let v3561: f64 = v25 * v3560;
        let v3562: f64 = v3550 - v3561;
        let v3563: f64 = v18 * v3562;
        (
            v3369,
            v3370,
            v3391,
            v3393,
            v3395,
            v3400,
            v3413,
            v3416,
            v3441,
            v3447,
            v3451,
            v3455,
            v3456,
            v3464,
            v3466,
            v3476,
            v3488,
            v3491,
            v3492,
            v3494,
            v3496,
            v3499,
            v3519,
            v3522,
            v3538,
            v3540,
            v3544,
            v3545,
            v3549,
            v3559,
            v3560,
            v3563,
        )
    };
    let (
        v3575,
        v3585,
        v3589,
        v3592,
        v3596,
        v3603,
        v3618,
        v3661,
        v3680,
        v3696,
        v3709,
        v3711,
        v3714,
        v3715,
        v3740,
        v3741,
        v3750,
        v3757,
        v3759,
        v3760,
        v3761,
    ) = {
        let v3564: f64 = v57 * v3466;
        let v3565: f64 = v54 * v3519;
        let v3566: f64 = v3564 + v3565;
        let v3567: f64 = v363 - v3566;
        let v3568: f64 = v75 * v3559;
        let v3569: f64 = v3567 + v3568;
        let v3570: f64 = v25 * v3549;
        let v3571: f64 = v23 * v3560;
        let v3572: f64 = v3570 + v3571;
        let v3573: f64 = v40 * v3572;
        let v3574: f64 = v3569 + v3573;
        let v3575: f64 = v3563 - v3574;
        let v3576: f64 = v4 * v3575;
        let v3577: f64 = v3545 - v3576;
        let v3578: f64 = v3577 * v14;
        let v3579: f64 = v25 * v3522;
        let v3580: f64 = v23 * v3540;
        let v3581: f64 = v3579 + v3580;
        let v3582: f64 = v40 * v3538;
        let v3583: f64 = v3581 + v3582;
        let v3584: f64 = v3583 * v6;
        let v3585: f64 = v3578 + v3584;
        let v3586: f64 = v3352 + v3585;
        let v3587: f64 = v0 * v3586;
        let v3588: f64 = v3587 * v1496;
        let v3589: f64 = v3043 + v3588;
        let v3590: f64 = v2 * v54;
        let v3591: f64 = v2082 * v57;
        let v3592: f64 = v3590 - v3591;
        let v3593: f64 = v55 * v3592;
        let v3594: f64 = v2082 * v54;
        let v3595: f64 = v2 * v57;
        let v3596: f64 = v3594 + v3595;
        let v3597: f64 = v61 * v3596;
        let v3598: f64 = v3593 - v3597;
        let v3599: f64 = v2111 * v54;
        let v3600: f64 = v2114 * v57;
        let v3601: f64 = v3599 - v3600;
        let v3602: f64 = v80 * v3592;
        let v3603: f64 = v3601 + v3602;
        let v3604: f64 = v70 * v3603;
        let v3605: f64 = v3598 + v3604;
        let v3606: f64 = v91 * v3592;
        let v3607: f64 = v92 * v3606;
        let v3608: f64 = v94 * v3592;
        let v3609: f64 = v98 * v3608;
        let v3610: f64 = v3607 - v3609;
        let v3611: f64 = v104 * v3596;
        let v3612: f64 = v3610 + v3611;
        let v3613: f64 = v107 * v3603;
        let v3614: f64 = v2111 * v57;
        let v3615: f64 = v2114 * v54;
        let v3616: f64 = v3614 + v3615;
        let v3617: f64 = v80 * v3596;
        let v3618: f64 = v3616 + v3617;
        let v3619: f64 = v94 * v3618;
        let v3620: f64 = v109 * v3619;
        let v3621: f64 = v3613 - v3620;
        let v3622: f64 = v3612 + v3621;
        let v3623: f64 = v122 * v3606;
        let v3624: f64 = v125 * v3596;
        let v3625: f64 = v3623 + v3624;
        let v3626: f64 = v123 * v3625;
        let v3627: f64 = v122 * v3596;
        let v3628: f64 = v125 * v3606;
        let v3629: f64 = v3627 - v3628;
        let v3630: f64 = v129 * v3629;
        let v3631: f64 = v3626 + v3630;
        let v3632: f64 = v135 * v3608;
        let v3633: f64 = v3631 + v3632;
        let v3634: f64 = v139 * v3596;
        let v3635: f64 = v3634 + v3619;
        let v3636: f64 = v138 * v3635;
        let v3637: f64 = v139 * v3608;
        let v3638: f64 = v3603 + v3637;
        let v3639: f64 = v122 * v3638;
        let v3640: f64 = v91 * v3618;
        let v3641: f64 = v125 * v3640;
        let v3642: f64 = v3639 + v3641;
        let v3643: f64 = v143 * v3642;
        let v3644: f64 = v3636 + v3643;
        let v3645: f64 = v3633 - v3644;
        let v3646: f64 = v122 * v3645;
        let v3647: f64 = v129 * v3625;
        let v3648: f64 = v157 * v3629;
        let v3649: f64 = v3647 + v3648;
        let v3650: f64 = v160 * v3608;
        let v3651: f64 = v3649 + v3650;
        let v3652: f64 = v125 * v3638;
        let v3653: f64 = v122 * v3640;
        let v3654: f64 = v3652 - v3653;
        let v3655: f64 = v143 * v3654;
        let v3656: f64 = v167 * v3635;
        let v3657: f64 = v3655 + v3656;
        let v3658: f64 = v3651 + v3657;
        let v3659: f64 = v125 * v3658;
        let v3660: f64 = v3646 - v3659;
        let v3661: f64 = v3622 + v3660;
        let v3662: f64 = v91 * v3661;
        let v3663: f64 = v98 * v3606;
        let v3664: f64 = v176 * v3608;
        let v3665: f64 = v3663 - v3664;
        let v3666: f64 = v179 * v3596;
        let v3667: f64 = v3665 + v3666;
        let v3668: f64 = v109 * v3640;
        let v3669: f64 = v183 * v3603;
        let v3670: f64 = v3668 + v3669;
        let v3671: f64 = v3667 - v3670;
        let v3672: f64 = v135 * v3625;
        let v3673: f64 = v160 * v3629;
        let v3674: f64 = v3672 + v3673;
        let v3675: f64 = v190 * v3608;
        let v3676: f64 = v3674 + v3675;
        let v3677: f64 = v167 * v3642;
        let v3678: f64 = v138 * v3654;
        let v3679: f64 = v3677 - v3678;
        let v3680: f64 = v3676 + v3679;
        let v3681: f64 = v3671 - v3680;
        let v3682: f64 = v198 * v3654;
        let v3683: f64 = v143 * v3629;
        let v3684: f64 = v138 * v3608;
        let v3685: f64 = v3683 - v3684;
        let v3686: f64 = v3682 + v3685;
        let v3687: f64 = v125 * v3686;
        let v3688: f64 = v198 * v3642;
        let v3689: f64 = v167 * v3608;
        let v3690: f64 = v143 * v3625;
        let v3691: f64 = v3689 - v3690;
        let v3692: f64 = v3688 + v3691;
        let v3693: f64 = v122 * v3692;
        let v3694: f64 = v3687 + v3693;
        let v3695: f64 = v139 * v3694;
        let v3696: f64 = v3681 - v3695;
        let v3697: f64 = v94 * v3696;
        let v3698: f64 = v3662 - v3697;
        let v3699: f64 = v3605 + v3698;
        let v3700: f64 = v70 * v3592;
        let v3701: f64 = v221 * v3603;
        let v3702: f64 = v3700 + v3701;
        let v3703: f64 = v224 * v3603;
        let v3704: f64 = v107 * v3606;
        let v3705: f64 = v183 * v3608;
        let v3706: f64 = v3704 + v3705;
        let v3707: f64 = v3703 + v3706;
        let v3708: f64 = v3707 + v3694;
        let v3709: f64 = v3702 + v3708;
        let v3710: f64 = v80 * v3709;
        let v3711: f64 = v3699 + v3710;
        let v3712: f64 = v54 * v3711;
        let v3713: f64 = v2240 * v57;
        let v3714: f64 = v3712 - v3713;
        let v3715: f64 = v2297 * v54;
        let v3716: f64 = v61 * v3592;
        let v3717: f64 = v236 * v3596;
        let v3718: f64 = v3716 - v3717;
        let v3719: f64 = v70 * v3618;
        let v3720: f64 = v3718 - v3719;
        let v3721: f64 = v104 * v3606;
        let v3722: f64 = v179 * v3608;
        let v3723: f64 = v3721 - v3722;
        let v3724: f64 = v249 * v3596;
        let v3725: f64 = v3723 + v3724;
        let v3726: f64 = v183 * v3619;
        let v3727: f64 = v107 * v3640;
        let v3728: f64 = v3726 + v3727;
        let v3729: f64 = v3725 + v3728;
        let v3730: f64 = v125 * v3645;
        let v3731: f64 = v122 * v3658;
        let v3732: f64 = v3730 + v3731;
        let v3733: f64 = v3729 + v3732;
        let v3734: f64 = v138 * v3625;
        let v3735: f64 = v167 * v3629;
        let v3736: f64 = v3734 - v3735;
        let v3737: f64 = v198 * v3635;
        let v3738: f64 = v3736 - v3737;
        let v3739: f64 = v139 * v3738;
        let v3740: f64 = v3733 - v3739;
        let v3741: f64 = v3720 - v3740;
        let v3742: f64 = v122 * v3686;
        let v3743: f64 = v125 * v3692;
        let v3744: f64 = v3742 - v3743;
        let v3745: f64 = v224 * v3640;
        let v3746: f64 = v109 * v3608;
        let v3747: f64 = v107 * v3596;
        let v3748: f64 = v3746 + v3747;
        let v3749: f64 = v3745 + v3748;
        let v3750: f64 = v3744 - v3749;
        let v3751: f64 = v91 * v3750;
        let v3752: f64 = v183 * v3596;
        let v3753: f64 = v109 * v3606;
        let v3754: f64 = v3752 - v3753;
        let v3755: f64 = v224 * v3619;
        let v3756: f64 = v3754 + v3755;
        let v3757: f64 = v3756 - v3738;
        let v3758: f64 = v94 * v3757;
        let v3759: f64 = v3751 - v3758;
        let v3760: f64 = v221 * v3618;
        let v3761: f64 = v70 * v3596;
        (
            v3575,
            v3585,
            v3589,
            v3592,
            v3596,
            v3603,
            v3618,
            v3661,
            v3680,
            v3696,
            v3709,
            v3711,
            v3714,
            v3715,
            v3740,
            v3741,
            v3750,
            v3757,
            v3759,
            v3760,
            v3761,
        )
    };
    let (
        v3780,
        v3793,
        v3821,
        v3827,
        v3835,
        v3837,
        v3839,
        v3848,
        v3851,
        v3860,
        v3863,
        v3865,
        v3882,
        v3888,
        v3892,
        v3900,
        v3902,
        v3917,
        v3921,
        v3923,
        v3924,
        v3927,
        v3929,
        v3931,
        v3939,
        v3941,
        v3945,
        v3946,
        v3949,
        v3953,
        v3956,
        v3957,
        v3958,
        v3959,
    ) = {
        let v3762: f64 = v3760 + v3761;
        let v3763: f64 = v3759 - v3762;
        let v3764: f64 = v80 * v3763;
        let v3765: f64 = v3741 + v3764;
        let v3766: f64 = v57 * v3765;
        let v3767: f64 = v3715 + v3766;
        let v3768: f64 = v3714 - v3767;
        let v3769: f64 = v23 * v3768;
        let v3770: f64 = v67 * v3592;
        let v3771: f64 = v239 * v3596;
        let v3772: f64 = v3770 - v3771;
        let v3773: f64 = v217 * v3603;
        let v3774: f64 = v84 * v3618;
        let v3775: f64 = v3773 - v3774;
        let v3776: f64 = v3772 - v3775;
        let v3777: f64 = v94 * v3661;
        let v3778: f64 = v91 * v3696;
        let v3779: f64 = v3777 + v3778;
        let v3780: f64 = v3776 + v3779;
        let v3781: f64 = v2295 * v54;
        let v3782: f64 = v57 * v3763;
        let v3783: f64 = v3781 + v3782;
        let v3784: f64 = v54 * v3709;
        let v3785: f64 = v2238 * v57;
        let v3786: f64 = v3784 - v3785;
        let v3787: f64 = v3783 - v3786;
        let v3788: f64 = v75 * v3787;
        let v3789: f64 = v3780 + v3788;
        let v3790: f64 = v25 * v3789;
        let v3791: f64 = v3769 - v3790;
        let v3792: f64 = v18 * v3787;
        let v3793: f64 = v3791 - v3792;
        let v3794: f64 = v2 * v3793;
        let v3795: f64 = v54 * v3763;
        let v3796: f64 = v2295 * v57;
        let v3797: f64 = v3795 - v3796;
        let v3798: f64 = v2238 * v54;
        let v3799: f64 = v57 * v3709;
        let v3800: f64 = v3798 + v3799;
        let v3801: f64 = v3797 + v3800;
        let v3802: f64 = v23 * v3801;
        let v3803: f64 = v84 * v3592;
        let v3804: f64 = v217 * v3596;
        let v3805: f64 = v3803 + v3804;
        let v3806: f64 = v94 * v3750;
        let v3807: f64 = v91 * v3757;
        let v3808: f64 = v3806 + v3807;
        let v3809: f64 = v3805 + v3808;
        let v3810: f64 = v25 * v3809;
        let v3811: f64 = v3802 - v3810;
        let v3812: f64 = v18 * v3811;
        let v3813: f64 = v75 * v3809;
        let v3814: f64 = v2240 * v54;
        let v3815: f64 = v57 * v3711;
        let v3816: f64 = v3814 + v3815;
        let v3817: f64 = v54 * v3765;
        let v3818: f64 = v2297 * v57;
        let v3819: f64 = v3817 - v3818;
        let v3820: f64 = v3816 + v3819;
        let v3821: f64 = v3813 - v3820;
        let v3822: f64 = v25 * v3801;
        let v3823: f64 = v23 * v3809;
        let v3824: f64 = v3822 + v3823;
        let v3825: f64 = v40 * v3824;
        let v3826: f64 = v3821 + v3825;
        let v3827: f64 = v3812 - v3826;
        let v3828: f64 = v4 * v3827;
        let v3829: f64 = v3794 - v3828;
        let v3830: f64 = v6 * v3829;
        let v3831: f64 = v25 * v3768;
        let v3832: f64 = v23 * v3789;
        let v3833: f64 = v3831 + v3832;
        let v3834: f64 = v40 * v3787;
        let v3835: f64 = v3833 + v3834;
        let v3836: f64 = v14 * v3835;
        let v3837: f64 = v3830 - v3836;
        let v3838: f64 = v92 * v94;
        let v3839: f64 = v98 * v91;
        let v3840: f64 = v3838 + v3839;
        let v3841: f64 = v122 * v94;
        let v3842: f64 = v123 * v3841;
        let v3843: f64 = v125 * v94;
        let v3844: f64 = v129 * v3843;
        let v3845: f64 = v3842 - v3844;
        let v3846: f64 = v135 * v91;
        let v3847: f64 = v3845 - v3846;
        let v3848: f64 = v139 * v91;
        let v3849: f64 = v122 * v3848;
        let v3850: f64 = v143 * v3849;
        let v3851: f64 = v3847 + v3850;
        let v3852: f64 = v122 * v3851;
        let v3853: f64 = v129 * v3841;
        let v3854: f64 = v157 * v3843;
        let v3855: f64 = v3853 - v3854;
        let v3856: f64 = v160 * v91;
        let v3857: f64 = v3855 - v3856;
        let v3858: f64 = v125 * v3848;
        let v3859: f64 = v143 * v3858;
        let v3860: f64 = v3857 - v3859;
        let v3861: f64 = v125 * v3860;
        let v3862: f64 = v3852 - v3861;
        let v3863: f64 = v3840 + v3862;
        let v3864: f64 = v91 * v3863;
        let v3865: f64 = v98 * v94;
        let v3866: f64 = v176 * v91;
        let v3867: f64 = v3865 + v3866;
        let v3868: f64 = v135 * v3841;
        let v3869: f64 = v160 * v3843;
        let v3870: f64 = v3868 - v3869;
        let v3871: f64 = v190 * v91;
        let v3872: f64 = v3870 - v3871;
        let v3873: f64 = v138 * v3858;
        let v3874: f64 = v167 * v3849;
        let v3875: f64 = v3873 - v3874;
        let v3876: f64 = v3872 + v3875;
        let v3877: f64 = v3867 - v3876;
        let v3878: f64 = v138 * v91;
        let v3879: f64 = v143 * v3843;
        let v3880: f64 = v3878 - v3879;
        let v3881: f64 = v198 * v3858;
        let v3882: f64 = v3880 - v3881;
        let v3883: f64 = v125 * v3882;
        let v3884: f64 = v198 * v3849;
        let v3885: f64 = v167 * v91;
        let v3886: f64 = v143 * v3841;
        let v3887: f64 = v3885 + v3886;
        let v3888: f64 = v3884 + v3887;
        let v3889: f64 = v122 * v3888;
        let v3890: f64 = v3883 - v3889;
        let v3891: f64 = v139 * v3890;
        let v3892: f64 = v3877 - v3891;
        let v3893: f64 = v94 * v3892;
        let v3894: f64 = v3864 - v3893;
        let v3895: f64 = v67 + v3894;
        let v3896: f64 = v107 * v94;
        let v3897: f64 = v183 * v91;
        let v3898: f64 = v3896 - v3897;
        let v3899: f64 = v3898 + v3890;
        let v3900: f64 = v217 - v3899;
        let v3901: f64 = v80 * v3900;
        let v3902: f64 = v3895 - v3901;
        let v3903: f64 = v54 * v3902;
        let v3904: f64 = v104 * v94;
        let v3905: f64 = v179 * v91;
        let v3906: f64 = v3904 + v3905;
        let v3907: f64 = v125 * v3851;
        let v3908: f64 = v122 * v3860;
        let v3909: f64 = v3907 + v3908;
        let v3910: f64 = v3906 + v3909;
        let v3911: f64 = v138 * v3841;
        let v3912: f64 = v167 * v3843;
        let v3913: f64 = v3911 + v3912;
        let v3914: f64 = v139 * v3913;
        let v3915: f64 = v3910 - v3914;
        let v3916: f64 = v239 - v3915;
        let v3917: f64 = v109 * v91;
        let v3918: f64 = v122 * v3882;
        let v3919: f64 = v125 * v3888;
        let v3920: f64 = v3918 + v3919;
        let v3921: f64 = v3917 + v3920;
        let v3922: f64 = v91 * v3921;
        let v3923: f64 = v109 * v94;
        let v3924: f64 = v3923 + v3913;
        let v3925: f64 = v94 * v3924;
        let v3926: f64 = v3922 + v3925;
        let v3927: f64 = v3926 - v84;
        let v3928: f64 = v80 * v3927;
        let v3929: f64 = v3916 + v3928;
        let v3930: f64 = v57 * v3929;
        let v3931: f64 = v3903 - v3930;
        let v3932: f64 = v23 * v3931;
        let v3933: f64 = v94 * v3863;
        let v3934: f64 = v91 * v3892;
        let v3935: f64 = v3933 + v3934;
        let v3936: f64 = v313 + v3935;
        let v3937: f64 = v57 * v3927;
        let v3938: f64 = v54 * v3900;
        let v3939: f64 = v3937 + v3938;
        let v3940: f64 = v75 * v3939;
        let v3941: f64 = v3936 + v3940;
        let v3942: f64 = v25 * v3941;
        let v3943: f64 = v3932 - v3942;
        let v3944: f64 = v18 * v3939;
        let v3945: f64 = v3943 - v3944;
        let v3946: f64 = v2 * v3945;
        let v3947: f64 = v54 * v3927;
        let v3948: f64 = v57 * v3900;
        let v3949: f64 = v3947 - v3948;
        let v3950: f64 = v23 * v3949;
        let v3951: f64 = v94 * v3921;
        let v3952: f64 = v91 * v3924;
        let v3953: f64 = v3951 - v3952;
        let v3954: f64 = v25 * v3953;
        let v3955: f64 = v3950 - v3954;
        let v3956: f64 = v18 * v3955;
        let v3957: f64 = v75 * v3953;
        let v3958: f64 = v57 * v3902;
        let v3959: f64 = v54 * v3929;
        (
            v3780,
            v3793,
            v3821,
            v3827,
            v3835,
            v3837,
            v3839,
            v3848,
            v3851,
            v3860,
            v3863,
            v3865,
            v3882,
            v3888,
            v3892,
            v3900,
            v3902,
            v3917,
            v3921,
            v3923,
            v3924,
            v3927,
            v3929,
            v3931,
            v3939,
            v3941,
            v3945,
            v3946,
            v3949,
            v3953,
            v3956,
            v3957,
            v3958,
            v3959,
        )
    };
    let (
        v3967,
        v3977,
        v3981,
        v4047,
        v4110,
        v4113,
        v4121,
        v4124,
        v4126,
        v4130,
        v4131,
        v4150,
        v4156,
        v4157,
    ) = {
        let v3960: f64 = v3958 + v3959;
        let v3961: f64 = v3957 - v3960;
        let v3962: f64 = v25 * v3949;
        let v3963: f64 = v23 * v3953;
        let v3964: f64 = v3962 + v3963;
        let v3965: f64 = v40 * v3964;
        let v3966: f64 = v3961 + v3965;
        let v3967: f64 = v3956 - v3966;
        let v3968: f64 = v4 * v3967;
        let v3969: f64 = v3946 - v3968;
        let v3970: f64 = v3969 * v14;
        let v3971: f64 = v25 * v3931;
        let v3972: f64 = v23 * v3941;
        let v3973: f64 = v3971 + v3972;
        let v3974: f64 = v40 * v3939;
        let v3975: f64 = v3973 + v3974;
        let v3976: f64 = v3975 * v6;
        let v3977: f64 = v3970 + v3976;
        let v3978: f64 = v3837 + v3977;
        let v3979: f64 = v0 * v3978;
        let v3980: f64 = v3979 * v1748;
        let v3981: f64 = v3589 + v3980;
        let v3982: f64 = v2142 * v91;
        let v3983: f64 = v2121 * v94;
        let v3984: f64 = v3982 - v3983;
        let v3985: f64 = v109 * v3984;
        let v3986: f64 = v2100 * v94;
        let v3987: f64 = v2084 * v91;
        let v3988: f64 = v3986 + v3987;
        let v3989: f64 = v92 * v3988;
        let v3990: f64 = v2100 * v91;
        let v3991: f64 = v2084 * v94;
        let v3992: f64 = v3990 - v3991;
        let v3993: f64 = v98 * v3992;
        let v3994: f64 = v3989 + v3993;
        let v3995: f64 = v3985 - v3994;
        let v3996: f64 = v125 * v3988;
        let v3997: f64 = v129 * v3996;
        let v3998: f64 = v122 * v3988;
        let v3999: f64 = v123 * v3998;
        let v4000: f64 = v3997 - v3999;
        let v4001: f64 = v135 * v3992;
        let v4002: f64 = v4000 + v4001;
        let v4003: f64 = v139 * v3992;
        let v4004: f64 = v122 * v4003;
        let v4005: f64 = v2142 * v94;
        let v4006: f64 = v2121 * v91;
        let v4007: f64 = v4005 + v4006;
        let v4008: f64 = v125 * v4007;
        let v4009: f64 = v4004 + v4008;
        let v4010: f64 = v143 * v4009;
        let v4011: f64 = v138 * v3984;
        let v4012: f64 = v4010 - v4011;
        let v4013: f64 = v4002 - v4012;
        let v4014: f64 = v122 * v4013;
        let v4015: f64 = v157 * v3996;
        let v4016: f64 = v129 * v3998;
        let v4017: f64 = v4015 - v4016;
        let v4018: f64 = v160 * v3992;
        let v4019: f64 = v4017 + v4018;
        let v4020: f64 = v125 * v4003;
        let v4021: f64 = v122 * v4007;
        let v4022: f64 = v4020 - v4021;
        let v4023: f64 = v143 * v4022;
        let v4024: f64 = v167 * v3984;
        let v4025: f64 = v4023 - v4024;
        let v4026: f64 = v4019 + v4025;
        let v4027: f64 = v125 * v4026;
        let v4028: f64 = v4014 - v4027;
        let v4029: f64 = v3995 + v4028;
        let v4030: f64 = v91 * v4029;
        let v4031: f64 = v2188 * v94;
        let v4032: f64 = v4030 - v4031;
        let v4033: f64 = v2223 * v91;
        let v4034: f64 = v98 * v3988;
        let v4035: f64 = v176 * v3992;
        let v4036: f64 = v4034 + v4035;
        let v4037: f64 = v109 * v4007;
        let v4038: f64 = v4036 + v4037;
        let v4039: f64 = v160 * v3996;
        let v4040: f64 = v135 * v3998;
        let v4041: f64 = v4039 - v4040;
        let v4042: f64 = v190 * v3992;
        let v4043: f64 = v4041 + v4042;
        let v4044: f64 = v167 * v4009;
        let v4045: f64 = v138 * v4022;
        let v4046: f64 = v4044 - v4045;
        let v4047: f64 = v4043 + v4046;
        let v4048: f64 = v4038 + v4047;
        let v4049: f64 = v198 * v4022;
        let v4050: f64 = v143 * v3996;
        let v4051: f64 = v138 * v3992;
        let v4052: f64 = v4050 - v4051;
        let v4053: f64 = v4049 + v4052;
        let v4054: f64 = v125 * v4053;
        let v4055: f64 = v198 * v4009;
        let v4056: f64 = v167 * v3992;
        let v4057: f64 = v143 * v3998;
        let v4058: f64 = v4056 + v4057;
        let v4059: f64 = v4055 + v4058;
        let v4060: f64 = v122 * v4059;
        let v4061: f64 = v4054 + v4060;
        let v4062: f64 = v139 * v4061;
        let v4063: f64 = v4048 + v4062;
        let v4064: f64 = v94 * v4063;
        let v4065: f64 = v4033 - v4064;
        let v4066: f64 = v4032 - v4065;
        let v4067: f64 = v183 * v3992;
        let v4068: f64 = v107 * v3988;
        let v4069: f64 = v4067 - v4068;
        let v4070: f64 = v4069 + v4061;
        let v4071: f64 = v80 * v4070;
        let v4072: f64 = v4066 + v4071;
        let v4073: f64 = v54 * v4072;
        let v4074: f64 = v122 * v4053;
        let v4075: f64 = v125 * v4059;
        let v4076: f64 = v4074 - v4075;
        let v4077: f64 = v224 * v4007;
        let v4078: f64 = v109 * v3992;
        let v4079: f64 = v4077 + v4078;
        let v4080: f64 = v4076 - v4079;
        let v4081: f64 = v91 * v4080;
        let v4082: f64 = v2285 * v94;
        let v4083: f64 = v4081 - v4082;
        let v4084: f64 = v2292 * v91;
        let v4085: f64 = v109 * v3988;
        let v4086: f64 = v224 * v3984;
        let v4087: f64 = v4085 - v4086;
        let v4088: f64 = v198 * v3984;
        let v4089: f64 = v138 * v3998;
        let v4090: f64 = v167 * v3996;
        let v4091: f64 = v4089 + v4090;
        let v4092: f64 = v4088 - v4091;
        let v4093: f64 = v4087 - v4092;
        let v4094: f64 = v94 * v4093;
        let v4095: f64 = v4084 + v4094;
        let v4096: f64 = v4083 - v4095;
        let v4097: f64 = v80 * v4096;
        let v4098: f64 = v125 * v4013;
        let v4099: f64 = v122 * v4026;
        let v4100: f64 = v4098 + v4099;
        let v4101: f64 = v104 * v3988;
        let v4102: f64 = v179 * v3992;
        let v4103: f64 = v4101 + v4102;
        let v4104: f64 = v183 * v3984;
        let v4105: f64 = v107 * v4007;
        let v4106: f64 = v4104 - v4105;
        let v4107: f64 = v4103 + v4106;
        let v4108: f64 = v4100 - v4107;
        let v4109: f64 = v139 * v4092;
        let v4110: f64 = v4108 - v4109;
        let v4111: f64 = v4097 - v4110;
        let v4112: f64 = v57 * v4111;
        let v4113: f64 = v4073 - v4112;
        let v4114: f64 = v23 * v4113;
        let v4115: f64 = v2188 * v91;
        let v4116: f64 = v94 * v4029;
        let v4117: f64 = v4115 + v4116;
        let v4118: f64 = v2223 * v94;
        let v4119: f64 = v91 * v4063;
        let v4120: f64 = v4118 + v4119;
        let v4121: f64 = v4117 - v4120;
        let v4122: f64 = v57 * v4096;
        let v4123: f64 = v54 * v4070;
        let v4124: f64 = v4122 - v4123;
        let v4125: f64 = v75 * v4124;
        let v4126: f64 = v4121 + v4125;
        let v4127: f64 = v25 * v4126;
        let v4128: f64 = v4114 - v4127;
        let v4129: f64 = v18 * v4124;
        let v4130: f64 = v4128 - v4129;
        let v4131: f64 = v2 * v4130;
        let v4132: f64 = v54 * v4096;
        let v4133: f64 = v57 * v4070;
        let v4134: f64 = v4132 + v4133;
        let v4135: f64 = v23 * v4134;
        let v4136: f64 = v2285 * v91;
        let v4137: f64 = v94 * v4080;
        let v4138: f64 = v4136 + v4137;
        let v4139: f64 = v91 * v4093;
        let v4140: f64 = v2292 * v94;
        let v4141: f64 = v4139 - v4140;
        let v4142: f64 = v4138 + v4141;
        let v4143: f64 = v25 * v4142;
        let v4144: f64 = v4135 - v4143;
        let v4145: f64 = v18 * v4144;
        let v4146: f64 = v75 * v4142;
        let v4147: f64 = v57 * v4072;
        let v4148: f64 = v54 * v4111;
        let v4149: f64 = v4147 + v4148;
        let v4150: f64 = v4146 - v4149;
        let v4151: f64 = v25 * v4134;
        let v4152: f64 = v23 * v4142;
        let v4153: f64 = v4151 + v4152;
        let v4154: f64 = v40 * v4153;
        let v4155: f64 = v4150 + v4154;
        let v4156: f64 = v4145 - v4155;
        let v4157: f64 = v4 * v4156;
        (
            v3967,
            v3977,
            v3981,
            v4047,
            v4110,
            v4113,
            v4121,
            v4124,
            v4126,
            v4130,
            v4131,
            v4150,
            v4156,
            v4157,
        )
    };
    let (
        v4164,
        v4166,
        v4168,
        v4171,
        v4173,
        v4177,
        v4180,
        v4184,
        v4186,
        v4187,
        v4188,
        v4189,
        v4190,
        v4192,
        v4196,
        v4198,
        v4199,
        v4201,
        v4203,
        v4204,
        v4208,
        v4210,
        v4218,
        v4220,
        v4229,
        v4233,
        v4237,
        v4241,
        v4255,
        v4265,
        v4269,
        v4306,
        v4319,
        v4325,
        v4333,
        v4337,
        v4339,
        v4349,
        v4350,
        v4352,
        v4353,
        v4354,
        v4355,
    ) = {
        let v4158: f64 = v4131 - v4157;
        let v4159: f64 = v6 * v4158;
        let v4160: f64 = v25 * v4113;
        let v4161: f64 = v23 * v4126;
        let v4162: f64 = v4160 + v4161;
        let v4163: f64 = v40 * v4124;
        let v4164: f64 = v4162 + v4163;
        let v4165: f64 = v14 * v4164;
        let v4166: f64 = v4159 - v4165;
        let v4167: f64 = v123 * v125;
        let v4168: f64 = v129 * v122;
        let v4169: f64 = v4167 + v4168;
        let v4170: f64 = v139 * v138;
        let v4171: f64 = v4169 - v4170;
        let v4172: f64 = v122 * v4171;
        let v4173: f64 = v129 * v125;
        let v4174: f64 = v157 * v122;
        let v4175: f64 = v4173 + v4174;
        let v4176: f64 = v139 * v167;
        let v4177: f64 = v4175 + v4176;
        let v4178: f64 = v125 * v4177;
        let v4179: f64 = v4172 - v4178;
        let v4180: f64 = v104 + v4179;
        let v4181: f64 = v91 * v4180;
        let v4182: f64 = v135 * v125;
        let v4183: f64 = v160 * v122;
        let v4184: f64 = v4182 + v4183;
        let v4185: f64 = v179 - v4184;
        let v4186: f64 = v143 * v122;
        let v4187: f64 = v125 * v4186;
        let v4188: f64 = v143 * v125;
        let v4189: f64 = v122 * v4188;
        let v4190: f64 = v4187 - v4189;
        let v4191: f64 = v139 * v4190;
        let v4192: f64 = v4185 - v4191;
        let v4193: f64 = v94 * v4192;
        let v4194: f64 = v4181 - v4193;
        let v4195: f64 = v80 * v4190;
        let v4196: f64 = v4194 + v4195;
        let v4197: f64 = v54 * v4196;
        let v4198: f64 = v122 * v4186;
        let v4199: f64 = v125 * v4188;
        let v4200: f64 = v4198 + v4199;
        let v4201: f64 = v4200 - v107;
        let v4202: f64 = v91 * v4201;
        let v4203: f64 = v138 * v125;
        let v4204: f64 = v167 * v122;
        let v4205: f64 = v4203 - v4204;
        let v4206: f64 = v139 * v198;
        let v4207: f64 = v4205 - v4206;
        let v4208: f64 = v183 - v4207;
        let v4209: f64 = v94 * v4208;
        let v4210: f64 = v4202 - v4209;
        let v4211: f64 = v80 * v4210;
        let v4212: f64 = v125 * v4171;
        let v4213: f64 = v122 * v4177;
        let v4214: f64 = v4212 + v4213;
        let v4215: f64 = v249 + v4214;
        let v4216: f64 = v139 * v4207;
        let v4217: f64 = v4215 - v4216;
        let v4218: f64 = v4211 - v4217;
        let v4219: f64 = v57 * v4218;
        let v4220: f64 = v4197 - v4219;
        let v4221: f64 = v23 * v4220;
        let v4222: f64 = v94 * v4180;
        let v4223: f64 = v91 * v4192;
        let v4224: f64 = v4222 + v4223;
        let v4225: f64 = v57 * v4210;
        let v4226: f64 = v54 * v4190;
        let v4227: f64 = v4225 - v4226;
        let v4228: f64 = v75 * v4227;
        let v4229: f64 = v4224 + v4228;
        let v4230: f64 = v25 * v4229;
        let v4231: f64 = v4221 - v4230;
        let v4232: f64 = v18 * v4227;
        let v4233: f64 = v4231 - v4232;
        let v4234: f64 = v2 * v4233;
        let v4235: f64 = v54 * v4210;
        let v4236: f64 = v57 * v4190;
        let v4237: f64 = v4235 + v4236;
        let v4238: f64 = v23 * v4237;
        let v4239: f64 = v94 * v4201;
        let v4240: f64 = v91 * v4208;
        let v4241: f64 = v4239 + v4240;
        let v4242: f64 = v25 * v4241;
        let v4243: f64 = v4238 - v4242;
        let v4244: f64 = v18 * v4243;
        let v4245: f64 = v75 * v4241;
        let v4246: f64 = v57 * v4196;
        let v4247: f64 = v54 * v4218;
        let v4248: f64 = v4246 + v4247;
        let v4249: f64 = v4245 - v4248;
        let v4250: f64 = v25 * v4237;
        let v4251: f64 = v23 * v4241;
        let v4252: f64 = v4250 + v4251;
        let v4253: f64 = v40 * v4252;
        let v4254: f64 = v4249 + v4253;
        let v4255: f64 = v4244 - v4254;
        let v4256: f64 = v4 * v4255;
        let v4257: f64 = v4234 - v4256;
        let v4258: f64 = v4257 * v14;
        let v4259: f64 = v25 * v4220;
        let v4260: f64 = v23 * v4229;
        let v4261: f64 = v4259 + v4260;
        let v4262: f64 = v40 * v4227;
        let v4263: f64 = v4261 + v4262;
        let v4264: f64 = v4263 * v6;
        let v4265: f64 = v4258 + v4264;
        let v4266: f64 = v4166 + v4265;
        let v4267: f64 = v0 * v4266;
        let v4268: f64 = v4267 * v1937;
        let v4269: f64 = v3981 + v4268;
        let v4270: f64 = v2104 * v122;
        let v4271: f64 = v2127 * v125;
        let v4272: f64 = v4270 - v4271;
        let v4273: f64 = v123 * v4272;
        let v4274: f64 = v2104 * v125;
        let v4275: f64 = v2127 * v122;
        let v4276: f64 = v4274 + v4275;
        let v4277: f64 = v129 * v4276;
        let v4278: f64 = v4273 - v4277;
        let v4279: f64 = v2163 * v125;
        let v4280: f64 = v2167 * v122;
        let v4281: f64 = v4279 + v4280;
        let v4282: f64 = v143 * v4281;
        let v4283: f64 = v4278 + v4282;
        let v4284: f64 = v122 * v4283;
        let v4285: f64 = v2172 * v125;
        let v4286: f64 = v4284 - v4285;
        let v4287: f64 = v2185 * v122;
        let v4288: f64 = v129 * v4272;
        let v4289: f64 = v157 * v4276;
        let v4290: f64 = v4288 - v4289;
        let v4291: f64 = v2163 * v122;
        let v4292: f64 = v2167 * v125;
        let v4293: f64 = v4291 - v4292;
        let v4294: f64 = v143 * v4293;
        let v4295: f64 = v4290 + v4294;
        let v4296: f64 = v125 * v4295;
        let v4297: f64 = v4287 + v4296;
        let v4298: f64 = v4286 - v4297;
        let v4299: f64 = v91 * v4298;
        let v4300: f64 = v135 * v4272;
        let v4301: f64 = v160 * v4276;
        let v4302: f64 = v4300 - v4301;
        let v4303: f64 = v167 * v4281;
        let v4304: f64 = v138 * v4293;
        let v4305: f64 = v4303 + v4304;
        let v4306: f64 = v4302 - v4305;
        let v4307: f64 = v2213 * v122;
        let v4308: f64 = v198 * v4293;
        let v4309: f64 = v143 * v4276;
        let v4310: f64 = v4308 - v4309;
        let v4311: f64 = v125 * v4310;
        let v4312: f64 = v4307 + v4311;
        let v4313: f64 = v2219 * v125;
        let v4314: f64 = v198 * v4281;
        let v4315: f64 = v143 * v4272;
        let v4316: f64 = v4314 + v4315;
        let v4317: f64 = v122 * v4316;
        let v4318: f64 = v4313 + v4317;
        let v4319: f64 = v4312 - v4318;
        let v4320: f64 = v139 * v4319;
        let v4321: f64 = v4306 + v4320;
        let v4322: f64 = v94 * v4321;
        let v4323: f64 = v4299 + v4322;
        let v4324: f64 = v80 * v4319;
        let v4325: f64 = v4323 + v4324;
        let v4326: f64 = v54 * v4325;
        let v4327: f64 = v122 * v4310;
        let v4328: f64 = v2213 * v125;
        let v4329: f64 = v4327 - v4328;
        let v4330: f64 = v2219 * v122;
        let v4331: f64 = v125 * v4316;
        let v4332: f64 = v4330 - v4331;
        let v4333: f64 = v4329 - v4332;
        let v4334: f64 = v91 * v4333;
        let v4335: f64 = v138 * v4272;
        let v4336: f64 = v167 * v4276;
        let v4337: f64 = v4335 + v4336;
        let v4338: f64 = v94 * v4337;
        let v4339: f64 = v4334 + v4338;
        let v4340: f64 = v80 * v4339;
        let v4341: f64 = v2172 * v122;
        let v4342: f64 = v125 * v4283;
        let v4343: f64 = v4341 + v4342;
        let v4344: f64 = v122 * v4295;
        let v4345: f64 = v2185 * v125;
        let v4346: f64 = v4344 - v4345;
        let v4347: f64 = v4343 + v4346;
        let v4348: f64 = v139 * v4337;
        let v4349: f64 = v4347 - v4348;
        let v4350: f64 = v4340 - v4349;
        let v4351: f64 = v57 * v4350;
        let v4352: f64 = v4326 - v4351;
        let v4353: f64 = v23 * v4352;
        let v4354: f64 = v94 * v4298;
        let v4355: f64 = v91 * v4321;
        (
            v4164,
            v4166,
            v4168,
            v4171,
            v4173,
            v4177,
            v4180,
            v4184,
            v4186,
            v4187,
            v4188,
            v4189,
            v4190,
            v4192,
            v4196,
            v4198,
            v4199,
            v4201,
            v4203,
            v4204,
            v4208,
            v4210,
            v4218,
            v4220,
            v4229,
            v4233,
            v4237,
            v4241,
            v4255,
            v4265,
            v4269,
            v4306,
            v4319,
            v4325,
            v4333,
            v4337,
            v4339,
            v4349,
            v4350,
            v4352,
            v4353,
            v4354,
            v4355,
        )
    };
    let (
        v4356,
        v4365,
        v4381,
        v4387,
        v4395,
        v4397,
        v4400,
        v4404,
        v4406,
        v4410,
        v4417,
        v4418,
        v4420,
        v4422,
        v4431,
        v4435,
        v4440,
        v4445,
        v4455,
        v4465,
        v4470,
        v4474,
        v4478,
        v4483,
        v4487,
        v4489,
        v4490,
        v4492,
        v4500,
        v4502,
        v4505,
        v4509,
        v4517,
        v4518,
        v4521,
        v4524,
        v4528,
        v4534,
        v4539,
        v4541,
        v4544,
        v4545,
        v4550,
        v4553,
    ) = {
        let v4356: f64 = v4354 - v4355;
        let v4357: f64 = v57 * v4339;
        let v4358: f64 = v54 * v4319;
        let v4359: f64 = v4357 - v4358;
        let v4360: f64 = v75 * v4359;
        let v4361: f64 = v4356 + v4360;
        let v4362: f64 = v25 * v4361;
        let v4363: f64 = v4353 - v4362;
        let v4364: f64 = v18 * v4359;
        let v4365: f64 = v4363 - v4364;
        let v4366: f64 = v2 * v4365;
        let v4367: f64 = v54 * v4339;
        let v4368: f64 = v57 * v4319;
        let v4369: f64 = v4367 + v4368;
        let v4370: f64 = v23 * v4369;
        let v4371: f64 = v94 * v4333;
        let v4372: f64 = v91 * v4337;
        let v4373: f64 = v4371 - v4372;
        let v4374: f64 = v25 * v4373;
        let v4375: f64 = v4370 - v4374;
        let v4376: f64 = v18 * v4375;
        let v4377: f64 = v75 * v4373;
        let v4378: f64 = v57 * v4325;
        let v4379: f64 = v54 * v4350;
        let v4380: f64 = v4378 + v4379;
        let v4381: f64 = v4377 - v4380;
        let v4382: f64 = v25 * v4369;
        let v4383: f64 = v23 * v4373;
        let v4384: f64 = v4382 + v4383;
        let v4385: f64 = v40 * v4384;
        let v4386: f64 = v4381 + v4385;
        let v4387: f64 = v4376 - v4386;
        let v4388: f64 = v4 * v4387;
        let v4389: f64 = v4366 - v4388;
        let v4390: f64 = v6 * v4389;
        let v4391: f64 = v25 * v4352;
        let v4392: f64 = v23 * v4361;
        let v4393: f64 = v4391 + v4392;
        let v4394: f64 = v40 * v4359;
        let v4395: f64 = v4393 + v4394;
        let v4396: f64 = v14 * v4395;
        let v4397: f64 = v4390 - v4396;
        let v4398: f64 = v122 * v135;
        let v4399: f64 = v125 * v160;
        let v4400: f64 = v4398 - v4399;
        let v4401: f64 = v91 * v4400;
        let v4402: f64 = v122 * v167;
        let v4403: f64 = v125 * v138;
        let v4404: f64 = v4402 - v4403;
        let v4405: f64 = v139 * v4404;
        let v4406: f64 = v190 + v4405;
        let v4407: f64 = v94 * v4406;
        let v4408: f64 = v4401 + v4407;
        let v4409: f64 = v80 * v4404;
        let v4410: f64 = v4408 + v4409;
        let v4411: f64 = v54 * v4410;
        let v4412: f64 = v125 * v135;
        let v4413: f64 = v122 * v160;
        let v4414: f64 = v4412 + v4413;
        let v4415: f64 = v122 * v138;
        let v4416: f64 = v125 * v167;
        let v4417: f64 = v4415 + v4416;
        let v4418: f64 = v91 * v4417;
        let v4419: f64 = v80 * v4418;
        let v4420: f64 = v4414 + v4419;
        let v4421: f64 = v57 * v4420;
        let v4422: f64 = v4411 + v4421;
        let v4423: f64 = v23 * v4422;
        let v4424: f64 = v94 * v4400;
        let v4425: f64 = v91 * v4406;
        let v4426: f64 = v4424 - v4425;
        let v4427: f64 = v57 * v4418;
        let v4428: f64 = v54 * v4404;
        let v4429: f64 = v4427 + v4428;
        let v4430: f64 = v75 * v4429;
        let v4431: f64 = v4426 - v4430;
        let v4432: f64 = v25 * v4431;
        let v4433: f64 = v4423 - v4432;
        let v4434: f64 = v18 * v4429;
        let v4435: f64 = v4433 + v4434;
        let v4436: f64 = v2 * v4435;
        let v4437: f64 = v57 * v4410;
        let v4438: f64 = v54 * v4420;
        let v4439: f64 = v4437 - v4438;
        let v4440: f64 = v94 * v4417;
        let v4441: f64 = v75 * v4440;
        let v4442: f64 = v4439 + v4441;
        let v4443: f64 = v57 * v4404;
        let v4444: f64 = v54 * v4418;
        let v4445: f64 = v4443 - v4444;
        let v4446: f64 = v25 * v4445;
        let v4447: f64 = v23 * v4440;
        let v4448: f64 = v4446 - v4447;
        let v4449: f64 = v40 * v4448;
        let v4450: f64 = v4442 - v4449;
        let v4451: f64 = v23 * v4445;
        let v4452: f64 = v25 * v4440;
        let v4453: f64 = v4451 + v4452;
        let v4454: f64 = v18 * v4453;
        let v4455: f64 = v4450 + v4454;
        let v4456: f64 = v4 * v4455;
        let v4457: f64 = v4436 - v4456;
        let v4458: f64 = v4457 * v14;
        let v4459: f64 = v25 * v4422;
        let v4460: f64 = v23 * v4431;
        let v4461: f64 = v4459 + v4460;
        let v4462: f64 = v40 * v4429;
        let v4463: f64 = v4461 - v4462;
        let v4464: f64 = v4463 * v6;
        let v4465: f64 = v4458 + v4464;
        let v4466: f64 = v4397 + v4465;
        let v4467: f64 = v0 * v4466;
        let v4468: f64 = v4467 * v2069;
        let v4469: f64 = v4269 + v4468;
        let v4470: f64 = -v4469;
        let v4471: f64 = v2992 * v4;
        let v4472: f64 = v3028 * v2;
        let v4473: f64 = v4471 + v4472;
        let v4474: f64 = v6 * v4473;
        let v4475: f64 = v4474 + v4474;
        let v4476: f64 = v0 * v4475;
        let v4477: f64 = v4476 * v1179;
        let v4478: f64 = v1178 * v2073;
        let v4479: f64 = v3039 + v2768;
        let v4480: f64 = v0 * v4479;
        let v4481: f64 = v4480 * v823;
        let v4482: f64 = v4478 + v4481;
        let v4483: f64 = v4477 - v4482;
        let v4484: f64 = v3544 * v4;
        let v4485: f64 = v3575 * v2;
        let v4486: f64 = v4484 + v4485;
        let v4487: f64 = v6 * v4486;
        let v4488: f64 = v24 * v23;
        let v4489: f64 = v4488 - v2957;
        let v4490: f64 = v54 * v23;
        let v4491: f64 = v55 * v4490;
        let v4492: f64 = v57 * v23;
        let v4493: f64 = v61 * v4492;
        let v4494: f64 = v4491 - v4493;
        let v4495: f64 = v67 * v25;
        let v4496: f64 = v4494 - v4495;
        let v4497: f64 = v75 * v25;
        let v4498: f64 = v54 * v4497;
        let v4499: f64 = v80 * v4490;
        let v4500: f64 = v4498 + v4499;
        let v4501: f64 = v70 * v4500;
        let v4502: f64 = v4496 + v4501;
        let v4503: f64 = v91 * v4490;
        let v4504: f64 = v94 * v25;
        let v4505: f64 = v4503 - v4504;
        let v4506: f64 = v92 * v4505;
        let v4507: f64 = v91 * v25;
        let v4508: f64 = v94 * v4490;
        let v4509: f64 = v4507 + v4508;
        let v4510: f64 = v98 * v4509;
        let v4511: f64 = v4506 - v4510;
        let v4512: f64 = v104 * v4492;
        let v4513: f64 = v4511 + v4512;
        let v4514: f64 = v107 * v4500;
        let v4515: f64 = v57 * v4497;
        let v4516: f64 = v80 * v4492;
        let v4517: f64 = v4515 + v4516;
        let v4518: f64 = v94 * v4517;
        let v4519: f64 = v109 * v4518;
        let v4520: f64 = v4514 - v4519;
        let v4521: f64 = v4513 + v4520;
        let v4522: f64 = v122 * v4505;
        let v4523: f64 = v125 * v4492;
        let v4524: f64 = v4522 + v4523;
        let v4525: f64 = v123 * v4524;
        let v4526: f64 = v122 * v4492;
        let v4527: f64 = v125 * v4505;
        let v4528: f64 = v4526 - v4527;
        let v4529: f64 = v129 * v4528;
        let v4530: f64 = v4525 + v4529;
        let v4531: f64 = v135 * v4509;
        let v4532: f64 = v4530 + v4531;
        let v4533: f64 = v139 * v4492;
        let v4534: f64 = v4518 + v4533;
        let v4535: f64 = v138 * v4534;
        let v4536: f64 = v139 * v4509;
        let v4537: f64 = v4500 + v4536;
        let v4538: f64 = v122 * v4537;
        let v4539: f64 = v91 * v4517;
        let v4540: f64 = v125 * v4539;
        let v4541: f64 = v4538 + v4540;
        let v4542: f64 = v143 * v4541;
        let v4543: f64 = v4535 + v4542;
        let v4544: f64 = v4532 - v4543;
        let v4545: f64 = v122 * v4544;
        let v4546: f64 = v129 * v4524;
        let v4547: f64 = v157 * v4528;
        let v4548: f64 = v4546 + v4547;
        let v4549: f64 = v160 * v4509;
        let v4550: f64 = v4548 + v4549;
        let v4551: f64 = v125 * v4537;
        let v4552: f64 = v122 * v4539;
        let v4553: f64 = v4551 - v4552;
        (
            v4356,
            v4365,
            v4381,
            v4387,
            v4395,
            v4397,
            v4400,
            v4404,
            v4406,
            v4410,
            v4417,
            v4418,
            v4420,
            v4422,
            v4431,
            v4435,
            v4440,
            v4445,
            v4455,
            v4465,
            v4470,
            v4474,
            v4478,
            v4483,
            v4487,
            v4489,
            v4490,
            v4492,
            v4500,
            v4502,
            v4505,
            v4509,
            v4517,
            v4518,
            v4521,
            v4524,
            v4528,
            v4534,
            v4539,
            v4541,
            v4544,
            v4545,
            v4550,
            v4553,
        )
    };
    let (v4579, v4640, v4689, v4702, v4704, v4734, v4744, v4747, v4750, v4751) = {
        let v4554: f64 = v143 * v4553;
        let v4555: f64 = v167 * v4534;
        let v4556: f64 = v4554 + v4555;
        let v4557: f64 = v4550 + v4556;
        let v4558: f64 = v125 * v4557;
        let v4559: f64 = v4545 - v4558;
        let v4560: f64 = v4521 + v4559;
        let v4561: f64 = v91 * v4560;
        let v4562: f64 = v98 * v4505;
        let v4563: f64 = v176 * v4509;
        let v4564: f64 = v4562 - v4563;
        let v4565: f64 = v179 * v4492;
        let v4566: f64 = v4564 + v4565;
        let v4567: f64 = v109 * v4539;
        let v4568: f64 = v183 * v4500;
        let v4569: f64 = v4567 + v4568;
        let v4570: f64 = v4566 - v4569;
        let v4571: f64 = v135 * v4524;
        let v4572: f64 = v160 * v4528;
        let v4573: f64 = v4571 + v4572;
        let v4574: f64 = v190 * v4509;
        let v4575: f64 = v4573 + v4574;
        let v4576: f64 = v167 * v4541;
        let v4577: f64 = v138 * v4553;
        let v4578: f64 = v4576 - v4577;
        let v4579: f64 = v4575 + v4578;
        let v4580: f64 = v4570 - v4579;
        let v4581: f64 = v198 * v4553;
        let v4582: f64 = v143 * v4528;
        let v4583: f64 = v138 * v4509;
        let v4584: f64 = v4582 - v4583;
        let v4585: f64 = v4581 + v4584;
        let v4586: f64 = v125 * v4585;
        let v4587: f64 = v198 * v4541;
        let v4588: f64 = v143 * v4524;
        let v4589: f64 = v167 * v4509;
        let v4590: f64 = v4588 - v4589;
        let v4591: f64 = v4587 - v4590;
        let v4592: f64 = v122 * v4591;
        let v4593: f64 = v4586 + v4592;
        let v4594: f64 = v139 * v4593;
        let v4595: f64 = v4580 - v4594;
        let v4596: f64 = v94 * v4595;
        let v4597: f64 = v4561 - v4596;
        let v4598: f64 = v4502 + v4597;
        let v4599: f64 = v217 * v25;
        let v4600: f64 = v70 * v4490;
        let v4601: f64 = v4599 + v4600;
        let v4602: f64 = v221 * v4500;
        let v4603: f64 = v4601 + v4602;
        let v4604: f64 = v224 * v4500;
        let v4605: f64 = v107 * v4505;
        let v4606: f64 = v183 * v4509;
        let v4607: f64 = v4605 + v4606;
        let v4608: f64 = v4604 + v4607;
        let v4609: f64 = v4608 + v4593;
        let v4610: f64 = v4603 + v4609;
        let v4611: f64 = v80 * v4610;
        let v4612: f64 = v4598 + v4611;
        let v4613: f64 = v54 * v4612;
        let v4614: f64 = v61 * v4490;
        let v4615: f64 = v236 * v4492;
        let v4616: f64 = v4614 - v4615;
        let v4617: f64 = v239 * v25;
        let v4618: f64 = v4616 - v4617;
        let v4619: f64 = v70 * v4517;
        let v4620: f64 = v4618 - v4619;
        let v4621: f64 = v104 * v4505;
        let v4622: f64 = v179 * v4509;
        let v4623: f64 = v4621 - v4622;
        let v4624: f64 = v249 * v4492;
        let v4625: f64 = v4623 + v4624;
        let v4626: f64 = v183 * v4518;
        let v4627: f64 = v107 * v4539;
        let v4628: f64 = v4626 + v4627;
        let v4629: f64 = v4625 + v4628;
        let v4630: f64 = v125 * v4544;
        let v4631: f64 = v122 * v4557;
        let v4632: f64 = v4630 + v4631;
        let v4633: f64 = v4629 + v4632;
        let v4634: f64 = v138 * v4524;
        let v4635: f64 = v167 * v4528;
        let v4636: f64 = v4634 - v4635;
        let v4637: f64 = v198 * v4534;
        let v4638: f64 = v4636 - v4637;
        let v4639: f64 = v139 * v4638;
        let v4640: f64 = v4633 - v4639;
        let v4641: f64 = v4620 - v4640;
        let v4642: f64 = v122 * v4585;
        let v4643: f64 = v125 * v4591;
        let v4644: f64 = v4642 - v4643;
        let v4645: f64 = v109 * v4509;
        let v4646: f64 = v107 * v4492;
        let v4647: f64 = v4645 + v4646;
        let v4648: f64 = v224 * v4539;
        let v4649: f64 = v4647 + v4648;
        let v4650: f64 = v4644 - v4649;
        let v4651: f64 = v91 * v4650;
        let v4652: f64 = v224 * v4518;
        let v4653: f64 = v183 * v4492;
        let v4654: f64 = v109 * v4505;
        let v4655: f64 = v4653 - v4654;
        let v4656: f64 = v4652 + v4655;
        let v4657: f64 = v4656 - v4638;
        let v4658: f64 = v94 * v4657;
        let v4659: f64 = v4651 - v4658;
        let v4660: f64 = v221 * v4517;
        let v4661: f64 = v70 * v4492;
        let v4662: f64 = v84 * v25;
        let v4663: f64 = v4661 - v4662;
        let v4664: f64 = v4660 + v4663;
        let v4665: f64 = v4659 - v4664;
        let v4666: f64 = v80 * v4665;
        let v4667: f64 = v4641 + v4666;
        let v4668: f64 = v57 * v4667;
        let v4669: f64 = v4613 - v4668;
        let v4670: f64 = v4489 + v4669;
        let v4671: f64 = v23 * v4670;
        let v4672: f64 = v2955 * v25;
        let v4673: f64 = v4671 - v4672;
        let v4674: f64 = v2980 * v23;
        let v4675: f64 = v299 * v25;
        let v4676: f64 = v2770 - v4675;
        let v4677: f64 = v67 * v4490;
        let v4678: f64 = v239 * v4492;
        let v4679: f64 = v4677 - v4678;
        let v4680: f64 = v313 * v25;
        let v4681: f64 = v4679 - v4680;
        let v4682: f64 = v217 * v4500;
        let v4683: f64 = v84 * v4517;
        let v4684: f64 = v4682 - v4683;
        let v4685: f64 = v4681 - v4684;
        let v4686: f64 = v94 * v4560;
        let v4687: f64 = v91 * v4595;
        let v4688: f64 = v4686 + v4687;
        let v4689: f64 = v4685 + v4688;
        let v4690: f64 = v4676 + v4689;
        let v4691: f64 = v57 * v4665;
        let v4692: f64 = v54 * v4610;
        let v4693: f64 = v4691 - v4692;
        let v4694: f64 = v75 * v4693;
        let v4695: f64 = v4690 + v4694;
        let v4696: f64 = v25 * v4695;
        let v4697: f64 = v4674 + v4696;
        let v4698: f64 = v4673 - v4697;
        let v4699: f64 = v39 * v23;
        let v4700: f64 = v306 * v25;
        let v4701: f64 = v4699 + v4700;
        let v4702: f64 = v4701 - v4693;
        let v4703: f64 = v18 * v4702;
        let v4704: f64 = v4698 + v4703;
        let v4705: f64 = v2 * v4704;
        let v4706: f64 = v54 * v4665;
        let v4707: f64 = v57 * v4610;
        let v4708: f64 = v4706 + v4707;
        let v4709: f64 = v4708 - v3017;
        let v4710: f64 = v23 * v4709;
        let v4711: f64 = v3015 * v25;
        let v4712: f64 = v4710 - v4711;
        let v4713: f64 = v3018 * v23;
        let v4714: f64 = v84 * v4490;
        let v4715: f64 = v217 * v4492;
        let v4716: f64 = v4714 + v4715;
        let v4717: f64 = v94 * v4650;
        let v4718: f64 = v91 * v4657;
        let v4719: f64 = v4717 + v4718;
        let v4720: f64 = v4716 + v4719;
        let v4721: f64 = v4720 - v3011;
        let v4722: f64 = v25 * v4721;
        let v4723: f64 = v4713 + v4722;
        let v4724: f64 = v4712 - v4723;
        let v4725: f64 = v18 * v4724;
        let v4726: f64 = v36 * v23;
        let v4727: f64 = v302 * v25;
        let v4728: f64 = v4726 - v4727;
        let v4729: f64 = v57 * v4612;
        let v4730: f64 = v54 * v4667;
        let v4731: f64 = v4729 + v4730;
        let v4732: f64 = v4728 - v4731;
        let v4733: f64 = v75 * v4720;
        let v4734: f64 = v4732 + v4733;
        let v4735: f64 = v3015 * v23;
        let v4736: f64 = v25 * v4709;
        let v4737: f64 = v4735 + v4736;
        let v4738: f64 = v23 * v4721;
        let v4739: f64 = v3018 * v25;
        let v4740: f64 = v4738 - v4739;
        let v4741: f64 = v4737 + v4740;
        let v4742: f64 = v40 * v4741;
        let v4743: f64 = v4734 + v4742;
        let v4744: f64 = v4725 - v4743;
        let v4745: f64 = v4 * v4744;
        let v4746: f64 = v4705 - v4745;
        let v4747: f64 = v6 * v4746;
        let v4748: f64 = v2955 * v23;
        let v4749: f64 = v25 * v4670;
        let v4750: f64 = v4748 + v4749;
        let v4751: f64 = v23 * v4695;
        (v4579, v4640, v4689, v4702, v4704, v4734, v4744, v4747, v4750, v4751)
    };
    let (
        v4756,
        v4758,
        v4760,
        v4762,
        v4766,
        v4767,
        v4773,
        v4844,
        v4878,
        v4880,
        v4893,
        v4905,
        v4911,
        v4932,
        v4934,
        v4937,
        v4938,
        v4949,
    ) = {
        let v4752: f64 = v2980 * v25;
        let v4753: f64 = v4751 - v4752;
        let v4754: f64 = v4750 + v4753;
        let v4755: f64 = v40 * v4702;
        let v4756: f64 = v4754 - v4755;
        let v4757: f64 = v14 * v4756;
        let v4758: f64 = v4747 - v4757;
        let v4759: f64 = v4487 - v4758;
        let v4760: f64 = v0 * v4759;
        let v4761: f64 = v4760 * v1496;
        let v4762: f64 = v4483 + v4761;
        let v4763: f64 = v3945 * v4;
        let v4764: f64 = v3967 * v2;
        let v4765: f64 = v4763 + v4764;
        let v4766: f64 = v6 * v4765;
        let v4767: f64 = v25 * v57;
        let v4768: f64 = v94 * v4767;
        let v4769: f64 = v98 * v4768;
        let v4770: f64 = v91 * v4767;
        let v4771: f64 = v92 * v4770;
        let v4772: f64 = v4769 - v4771;
        let v4773: f64 = v25 * v54;
        let v4774: f64 = v104 * v4773;
        let v4775: f64 = v4772 + v4774;
        let v4776: f64 = v2782 * v57;
        let v4777: f64 = v80 * v4767;
        let v4778: f64 = v4776 + v4777;
        let v4779: f64 = v107 * v4778;
        let v4780: f64 = v2782 * v54;
        let v4781: f64 = v80 * v4773;
        let v4782: f64 = v4780 + v4781;
        let v4783: f64 = v94 * v4782;
        let v4784: f64 = v109 * v4783;
        let v4785: f64 = v4779 + v4784;
        let v4786: f64 = v4775 - v4785;
        let v4787: f64 = v125 * v4773;
        let v4788: f64 = v122 * v4770;
        let v4789: f64 = v4787 - v4788;
        let v4790: f64 = v123 * v4789;
        let v4791: f64 = v122 * v4773;
        let v4792: f64 = v125 * v4770;
        let v4793: f64 = v4791 + v4792;
        let v4794: f64 = v129 * v4793;
        let v4795: f64 = v4790 + v4794;
        let v4796: f64 = v135 * v4768;
        let v4797: f64 = v4795 - v4796;
        let v4798: f64 = v139 * v4773;
        let v4799: f64 = v4783 + v4798;
        let v4800: f64 = v138 * v4799;
        let v4801: f64 = v91 * v4782;
        let v4802: f64 = v125 * v4801;
        let v4803: f64 = v139 * v4768;
        let v4804: f64 = v4778 + v4803;
        let v4805: f64 = v122 * v4804;
        let v4806: f64 = v4802 - v4805;
        let v4807: f64 = v143 * v4806;
        let v4808: f64 = v4800 + v4807;
        let v4809: f64 = v4797 - v4808;
        let v4810: f64 = v122 * v4809;
        let v4811: f64 = v129 * v4789;
        let v4812: f64 = v157 * v4793;
        let v4813: f64 = v4811 + v4812;
        let v4814: f64 = v160 * v4768;
        let v4815: f64 = v4813 - v4814;
        let v4816: f64 = v167 * v4799;
        let v4817: f64 = v125 * v4804;
        let v4818: f64 = v122 * v4801;
        let v4819: f64 = v4817 + v4818;
        let v4820: f64 = v143 * v4819;
        let v4821: f64 = v4816 - v4820;
        let v4822: f64 = v4815 + v4821;
        let v4823: f64 = v125 * v4822;
        let v4824: f64 = v4810 - v4823;
        let v4825: f64 = v4786 + v4824;
        let v4826: f64 = v91 * v4825;
        let v4827: f64 = v176 * v4768;
        let v4828: f64 = v98 * v4770;
        let v4829: f64 = v4827 - v4828;
        let v4830: f64 = v179 * v4773;
        let v4831: f64 = v4829 + v4830;
        let v4832: f64 = v109 * v4801;
        let v4833: f64 = v183 * v4778;
        let v4834: f64 = v4832 - v4833;
        let v4835: f64 = v4831 - v4834;
        let v4836: f64 = v135 * v4789;
        let v4837: f64 = v160 * v4793;
        let v4838: f64 = v4836 + v4837;
        let v4839: f64 = v190 * v4768;
        let v4840: f64 = v4838 - v4839;
        let v4841: f64 = v167 * v4806;
        let v4842: f64 = v138 * v4819;
        let v4843: f64 = v4841 + v4842;
        let v4844: f64 = v4840 + v4843;
        let v4845: f64 = v4835 - v4844;
        let v4846: f64 = v143 * v4793;
        let v4847: f64 = v138 * v4768;
        let v4848: f64 = v4846 + v4847;
        let v4849: f64 = v198 * v4819;
        let v4850: f64 = v4848 - v4849;
        let v4851: f64 = v125 * v4850;
        let v4852: f64 = v198 * v4806;
        let v4853: f64 = v167 * v4768;
        let v4854: f64 = v143 * v4789;
        let v4855: f64 = v4853 + v4854;
        let v4856: f64 = v4852 - v4855;
        let v4857: f64 = v122 * v4856;
        let v4858: f64 = v4851 + v4857;
        let v4859: f64 = v139 * v4858;
        let v4860: f64 = v4845 - v4859;
        let v4861: f64 = v94 * v4860;
        let v4862: f64 = v4826 - v4861;
        let v4863: f64 = v55 * v4767;
        let v4864: f64 = v61 * v4773;
        let v4865: f64 = v4863 + v4864;
        let v4866: f64 = v70 * v4778;
        let v4867: f64 = v4865 + v4866;
        let v4868: f64 = v4862 - v4867;
        let v4869: f64 = v70 * v4767;
        let v4870: f64 = v221 * v4778;
        let v4871: f64 = v4869 + v4870;
        let v4872: f64 = v224 * v4778;
        let v4873: f64 = v107 * v4770;
        let v4874: f64 = v183 * v4768;
        let v4875: f64 = v4873 + v4874;
        let v4876: f64 = v4872 + v4875;
        let v4877: f64 = v4858 - v4876;
        let v4878: f64 = v4871 - v4877;
        let v4879: f64 = v80 * v4878;
        let v4880: f64 = v4868 - v4879;
        let v4881: f64 = v54 * v4880;
        let v4882: f64 = v2897 * v57;
        let v4883: f64 = v4881 - v4882;
        let v4884: f64 = v2952 * v54;
        let v4885: f64 = v109 * v4768;
        let v4886: f64 = v107 * v4773;
        let v4887: f64 = v4885 - v4886;
        let v4888: f64 = v224 * v4801;
        let v4889: f64 = v4887 - v4888;
        let v4890: f64 = v122 * v4850;
        let v4891: f64 = v125 * v4856;
        let v4892: f64 = v4890 - v4891;
        let v4893: f64 = v4889 + v4892;
        let v4894: f64 = v91 * v4893;
        let v4895: f64 = v224 * v4783;
        let v4896: f64 = v183 * v4773;
        let v4897: f64 = v109 * v4770;
        let v4898: f64 = v4896 + v4897;
        let v4899: f64 = v4895 + v4898;
        let v4900: f64 = v138 * v4789;
        let v4901: f64 = v167 * v4793;
        let v4902: f64 = v4900 - v4901;
        let v4903: f64 = v198 * v4799;
        let v4904: f64 = v4902 - v4903;
        let v4905: f64 = v4899 - v4904;
        let v4906: f64 = v94 * v4905;
        let v4907: f64 = v4894 - v4906;
        let v4908: f64 = v221 * v4782;
        let v4909: f64 = v70 * v4773;
        let v4910: f64 = v4908 + v4909;
        let v4911: f64 = v4907 - v4910;
        let v4912: f64 = v80 * v4911;
        let v4913: f64 = v61 * v4767;
        let v4914: f64 = v236 * v4773;
        let v4915: f64 = v4913 + v4914;
        let v4916: f64 = v70 * v4782;
        let v4917: f64 = v4915 + v4916;
        let v4918: f64 = v179 * v4768;
        let v4919: f64 = v104 * v4770;
        let v4920: f64 = v4918 - v4919;
        let v4921: f64 = v249 * v4773;
        let v4922: f64 = v4920 + v4921;
        let v4923: f64 = v183 * v4783;
        let v4924: f64 = v107 * v4801;
        let v4925: f64 = v4923 + v4924;
        let v4926: f64 = v4922 + v4925;
        let v4927: f64 = v125 * v4809;
        let v4928: f64 = v122 * v4822;
        let v4929: f64 = v4927 + v4928;
        let v4930: f64 = v4926 + v4929;
        let v4931: f64 = v139 * v4904;
        let v4932: f64 = v4930 - v4931;
        let v4933: f64 = v4917 + v4932;
        let v4934: f64 = v4912 - v4933;
        let v4935: f64 = v57 * v4934;
        let v4936: f64 = v4884 + v4935;
        let v4937: f64 = v4883 - v4936;
        let v4938: f64 = v23 * v4937;
        let v4939: f64 = v217 * v4778;
        let v4940: f64 = v84 * v4782;
        let v4941: f64 = v4939 + v4940;
        let v4942: f64 = v67 * v4767;
        let v4943: f64 = v239 * v4773;
        let v4944: f64 = v4942 + v4943;
        let v4945: f64 = v4941 - v4944;
        let v4946: f64 = v94 * v4825;
        let v4947: f64 = v91 * v4860;
        let v4948: f64 = v4946 + v4947;
        let v4949: f64 = v4945 + v4948;
        (
            v4756,
            v4758,
            v4760,
            v4762,
            v4766,
            v4767,
            v4773,
            v4844,
            v4878,
            v4880,
            v4893,
            v4905,
            v4911,
            v4932,
            v4934,
            v4937,
            v4938,
            v4949,
        )
    };
    let (
        v4962,
        v4990,
        v4996,
        v5004,
        v5006,
        v5008,
        v5010,
        v5014,
        v5076,
        v5099,
        v5101,
        v5109,
        v5122,
        v5125,
        v5139,
        v5140,
        v5142,
        v5143,
        v5146,
        v5147,
    ) = {
        let v4950: f64 = v2950 * v54;
        let v4951: f64 = v57 * v4911;
        let v4952: f64 = v4950 + v4951;
        let v4953: f64 = v54 * v4878;
        let v4954: f64 = v2895 * v57;
        let v4955: f64 = v4953 - v4954;
        let v4956: f64 = v4952 + v4955;
        let v4957: f64 = v75 * v4956;
        let v4958: f64 = v4949 + v4957;
        let v4959: f64 = v25 * v4958;
        let v4960: f64 = v4938 - v4959;
        let v4961: f64 = v18 * v4956;
        let v4962: f64 = v4960 - v4961;
        let v4963: f64 = v2 * v4962;
        let v4964: f64 = v54 * v4911;
        let v4965: f64 = v2950 * v57;
        let v4966: f64 = v4964 - v4965;
        let v4967: f64 = v2895 * v54;
        let v4968: f64 = v57 * v4878;
        let v4969: f64 = v4967 + v4968;
        let v4970: f64 = v4966 - v4969;
        let v4971: f64 = v23 * v4970;
        let v4972: f64 = v217 * v4773;
        let v4973: f64 = v84 * v4767;
        let v4974: f64 = v4972 - v4973;
        let v4975: f64 = v94 * v4893;
        let v4976: f64 = v91 * v4905;
        let v4977: f64 = v4975 + v4976;
        let v4978: f64 = v4974 + v4977;
        let v4979: f64 = v25 * v4978;
        let v4980: f64 = v4971 - v4979;
        let v4981: f64 = v18 * v4980;
        let v4982: f64 = v75 * v4978;
        let v4983: f64 = v2897 * v54;
        let v4984: f64 = v57 * v4880;
        let v4985: f64 = v4983 + v4984;
        let v4986: f64 = v54 * v4934;
        let v4987: f64 = v2952 * v57;
        let v4988: f64 = v4986 - v4987;
        let v4989: f64 = v4985 + v4988;
        let v4990: f64 = v4982 - v4989;
        let v4991: f64 = v25 * v4970;
        let v4992: f64 = v23 * v4978;
        let v4993: f64 = v4991 + v4992;
        let v4994: f64 = v40 * v4993;
        let v4995: f64 = v4990 + v4994;
        let v4996: f64 = v4981 - v4995;
        let v4997: f64 = v4 * v4996;
        let v4998: f64 = v4963 - v4997;
        let v4999: f64 = v6 * v4998;
        let v5000: f64 = v25 * v4937;
        let v5001: f64 = v23 * v4958;
        let v5002: f64 = v5000 + v5001;
        let v5003: f64 = v40 * v4956;
        let v5004: f64 = v5002 + v5003;
        let v5005: f64 = v14 * v5004;
        let v5006: f64 = v4999 - v5005;
        let v5007: f64 = v4766 - v5006;
        let v5008: f64 = v0 * v5007;
        let v5009: f64 = v5008 * v1748;
        let v5010: f64 = v4762 + v5009;
        let v5011: f64 = v4233 * v4;
        let v5012: f64 = v4255 * v2;
        let v5013: f64 = v5011 + v5012;
        let v5014: f64 = v6 * v5013;
        let v5015: f64 = v23 * v91;
        let v5016: f64 = v2774 * v94;
        let v5017: f64 = v5015 - v5016;
        let v5018: f64 = v92 * v5017;
        let v5019: f64 = v23 * v94;
        let v5020: f64 = v2774 * v91;
        let v5021: f64 = v5019 + v5020;
        let v5022: f64 = v98 * v5021;
        let v5023: f64 = v5018 - v5022;
        let v5024: f64 = v2802 * v91;
        let v5025: f64 = v109 * v5024;
        let v5026: f64 = v5023 - v5025;
        let v5027: f64 = v122 * v5017;
        let v5028: f64 = v123 * v5027;
        let v5029: f64 = v125 * v5017;
        let v5030: f64 = v129 * v5029;
        let v5031: f64 = v5028 - v5030;
        let v5032: f64 = v135 * v5021;
        let v5033: f64 = v5031 + v5032;
        let v5034: f64 = v138 * v5024;
        let v5035: f64 = v139 * v5021;
        let v5036: f64 = v122 * v5035;
        let v5037: f64 = v2802 * v94;
        let v5038: f64 = v125 * v5037;
        let v5039: f64 = v5036 - v5038;
        let v5040: f64 = v143 * v5039;
        let v5041: f64 = v5034 + v5040;
        let v5042: f64 = v5033 - v5041;
        let v5043: f64 = v122 * v5042;
        let v5044: f64 = v129 * v5027;
        let v5045: f64 = v157 * v5029;
        let v5046: f64 = v5044 - v5045;
        let v5047: f64 = v160 * v5021;
        let v5048: f64 = v5046 + v5047;
        let v5049: f64 = v125 * v5035;
        let v5050: f64 = v122 * v5037;
        let v5051: f64 = v5049 + v5050;
        let v5052: f64 = v143 * v5051;
        let v5053: f64 = v167 * v5024;
        let v5054: f64 = v5052 + v5053;
        let v5055: f64 = v5048 + v5054;
        let v5056: f64 = v125 * v5055;
        let v5057: f64 = v5043 - v5056;
        let v5058: f64 = v5026 + v5057;
        let v5059: f64 = v91 * v5058;
        let v5060: f64 = v2845 * v94;
        let v5061: f64 = v5059 - v5060;
        let v5062: f64 = v2880 * v91;
        let v5063: f64 = v98 * v5017;
        let v5064: f64 = v176 * v5021;
        let v5065: f64 = v5063 - v5064;
        let v5066: f64 = v109 * v5037;
        let v5067: f64 = v5065 + v5066;
        let v5068: f64 = v135 * v5027;
        let v5069: f64 = v160 * v5029;
        let v5070: f64 = v5068 - v5069;
        let v5071: f64 = v190 * v5021;
        let v5072: f64 = v5070 + v5071;
        let v5073: f64 = v167 * v5039;
        let v5074: f64 = v138 * v5051;
        let v5075: f64 = v5073 - v5074;
        let v5076: f64 = v5072 + v5075;
        let v5077: f64 = v5067 - v5076;
        let v5078: f64 = v198 * v5051;
        let v5079: f64 = v143 * v5029;
        let v5080: f64 = v138 * v5021;
        let v5081: f64 = v5079 + v5080;
        let v5082: f64 = v5078 - v5081;
        let v5083: f64 = v125 * v5082;
        let v5084: f64 = v198 * v5039;
        let v5085: f64 = v143 * v5027;
        let v5086: f64 = v167 * v5021;
        let v5087: f64 = v5085 - v5086;
        let v5088: f64 = v5084 - v5087;
        let v5089: f64 = v122 * v5088;
        let v5090: f64 = v5083 + v5089;
        let v5091: f64 = v139 * v5090;
        let v5092: f64 = v5077 - v5091;
        let v5093: f64 = v94 * v5092;
        let v5094: f64 = v5062 + v5093;
        let v5095: f64 = v5061 - v5094;
        let v5096: f64 = v107 * v5017;
        let v5097: f64 = v183 * v5021;
        let v5098: f64 = v5096 + v5097;
        let v5099: f64 = v5098 + v5090;
        let v5100: f64 = v80 * v5099;
        let v5101: f64 = v5095 + v5100;
        let v5102: f64 = v54 * v5101;
        let v5103: f64 = v224 * v5037;
        let v5104: f64 = v109 * v5021;
        let v5105: f64 = v5103 - v5104;
        let v5106: f64 = v122 * v5082;
        let v5107: f64 = v125 * v5088;
        let v5108: f64 = v5106 - v5107;
        let v5109: f64 = v5105 + v5108;
        let v5110: f64 = v91 * v5109;
        let v5111: f64 = v2935 * v94;
        let v5112: f64 = v5110 - v5111;
        let v5113: f64 = v2942 * v91;
        let v5114: f64 = v224 * v5024;
        let v5115: f64 = v109 * v5017;
        let v5116: f64 = v5114 - v5115;
        let v5117: f64 = v138 * v5027;
        let v5118: f64 = v167 * v5029;
        let v5119: f64 = v5117 + v5118;
        let v5120: f64 = v198 * v5024;
        let v5121: f64 = v5119 - v5120;
        let v5122: f64 = v5116 - v5121;
        let v5123: f64 = v94 * v5122;
        let v5124: f64 = v5113 + v5123;
        let v5125: f64 = v5112 - v5124;
        let v5126: f64 = v80 * v5125;
        let v5127: f64 = v104 * v5017;
        let v5128: f64 = v179 * v5021;
        let v5129: f64 = v5127 - v5128;
        let v5130: f64 = v183 * v5024;
        let v5131: f64 = v107 * v5037;
        let v5132: f64 = v5130 - v5131;
        let v5133: f64 = v5129 + v5132;
        let v5134: f64 = v125 * v5042;
        let v5135: f64 = v122 * v5055;
        let v5136: f64 = v5134 + v5135;
        let v5137: f64 = v5133 + v5136;
        let v5138: f64 = v139 * v5121;
        let v5139: f64 = v5137 - v5138;
        let v5140: f64 = v5126 - v5139;
        let v5141: f64 = v57 * v5140;
        let v5142: f64 = v5102 - v5141;
        let v5143: f64 = v23 * v5142;
        let v5144: f64 = v2845 * v91;
        let v5145: f64 = v94 * v5058;
        let v5146: f64 = v5144 + v5145;
        let v5147: f64 = v91 * v5092;
        (
            v4962,
            v4990,
            v4996,
            v5004,
            v5006,
            v5008,
            v5010,
            v5014,
            v5076,
            v5099,
            v5101,
            v5109,
            v5122,
            v5125,
            v5139,
            v5140,
            v5142,
            v5143,
            v5146,
            v5147,
        )
    };
    let (
        v5150,
        v5159,
        v5179,
        v5185,
        v5193,
        v5195,
        v5197,
        v5203,
        v5240,
        v5283,
        v5290,
        v5299,
        v5315,
        v5321,
        v5329,
        v5331,
        v5333,
        v5335,
        v5337,
        v5342,
        v5345,
    ) = {
        let v5148: f64 = v2880 * v94;
        let v5149: f64 = v5147 - v5148;
        let v5150: f64 = v5146 + v5149;
        let v5151: f64 = v57 * v5125;
        let v5152: f64 = v54 * v5099;
        let v5153: f64 = v5151 - v5152;
        let v5154: f64 = v75 * v5153;
        let v5155: f64 = v5150 + v5154;
        let v5156: f64 = v25 * v5155;
        let v5157: f64 = v5143 - v5156;
        let v5158: f64 = v18 * v5153;
        let v5159: f64 = v5157 - v5158;
        let v5160: f64 = v2 * v5159;
        let v5161: f64 = v54 * v5125;
        let v5162: f64 = v57 * v5099;
        let v5163: f64 = v5161 + v5162;
        let v5164: f64 = v23 * v5163;
        let v5165: f64 = v2935 * v91;
        let v5166: f64 = v94 * v5109;
        let v5167: f64 = v5165 + v5166;
        let v5168: f64 = v91 * v5122;
        let v5169: f64 = v2942 * v94;
        let v5170: f64 = v5168 - v5169;
        let v5171: f64 = v5167 + v5170;
        let v5172: f64 = v25 * v5171;
        let v5173: f64 = v5164 - v5172;
        let v5174: f64 = v18 * v5173;
        let v5175: f64 = v75 * v5171;
        let v5176: f64 = v57 * v5101;
        let v5177: f64 = v54 * v5140;
        let v5178: f64 = v5176 + v5177;
        let v5179: f64 = v5175 - v5178;
        let v5180: f64 = v25 * v5163;
        let v5181: f64 = v23 * v5171;
        let v5182: f64 = v5180 + v5181;
        let v5183: f64 = v40 * v5182;
        let v5184: f64 = v5179 + v5183;
        let v5185: f64 = v5174 - v5184;
        let v5186: f64 = v4 * v5185;
        let v5187: f64 = v5160 - v5186;
        let v5188: f64 = v6 * v5187;
        let v5189: f64 = v25 * v5142;
        let v5190: f64 = v23 * v5155;
        let v5191: f64 = v5189 + v5190;
        let v5192: f64 = v40 * v5153;
        let v5193: f64 = v5191 + v5192;
        let v5194: f64 = v14 * v5193;
        let v5195: f64 = v5188 - v5194;
        let v5196: f64 = v5014 - v5195;
        let v5197: f64 = v0 * v5196;
        let v5198: f64 = v5197 * v1937;
        let v5199: f64 = v5010 + v5198;
        let v5200: f64 = v4435 * v4;
        let v5201: f64 = v4455 * v2;
        let v5202: f64 = v5200 + v5201;
        let v5203: f64 = v6 * v5202;
        let v5204: f64 = v2776 * v122;
        let v5205: f64 = v2790 * v125;
        let v5206: f64 = v5204 - v5205;
        let v5207: f64 = v123 * v5206;
        let v5208: f64 = v2776 * v125;
        let v5209: f64 = v2790 * v122;
        let v5210: f64 = v5208 + v5209;
        let v5211: f64 = v129 * v5210;
        let v5212: f64 = v5207 - v5211;
        let v5213: f64 = v2824 * v122;
        let v5214: f64 = v2822 * v125;
        let v5215: f64 = v5213 - v5214;
        let v5216: f64 = v143 * v5215;
        let v5217: f64 = v5212 - v5216;
        let v5218: f64 = v122 * v5217;
        let v5219: f64 = v2829 * v125;
        let v5220: f64 = v5218 - v5219;
        let v5221: f64 = v2842 * v122;
        let v5222: f64 = v129 * v5206;
        let v5223: f64 = v157 * v5210;
        let v5224: f64 = v5222 - v5223;
        let v5225: f64 = v2822 * v122;
        let v5226: f64 = v2824 * v125;
        let v5227: f64 = v5225 + v5226;
        let v5228: f64 = v143 * v5227;
        let v5229: f64 = v5224 + v5228;
        let v5230: f64 = v125 * v5229;
        let v5231: f64 = v5221 + v5230;
        let v5232: f64 = v5220 - v5231;
        let v5233: f64 = v91 * v5232;
        let v5234: f64 = v135 * v5206;
        let v5235: f64 = v160 * v5210;
        let v5236: f64 = v5234 - v5235;
        let v5237: f64 = v167 * v5215;
        let v5238: f64 = v138 * v5227;
        let v5239: f64 = v5237 - v5238;
        let v5240: f64 = v5236 + v5239;
        let v5241: f64 = v2870 * v122;
        let v5242: f64 = v198 * v5227;
        let v5243: f64 = v143 * v5210;
        let v5244: f64 = v5242 - v5243;
        let v5245: f64 = v125 * v5244;
        let v5246: f64 = v5241 + v5245;
        let v5247: f64 = v198 * v5215;
        let v5248: f64 = v143 * v5206;
        let v5249: f64 = v5247 - v5248;
        let v5250: f64 = v122 * v5249;
        let v5251: f64 = v2876 * v125;
        let v5252: f64 = v5250 - v5251;
        let v5253: f64 = v5246 + v5252;
        let v5254: f64 = v139 * v5253;
        let v5255: f64 = v5240 + v5254;
        let v5256: f64 = v94 * v5255;
        let v5257: f64 = v5233 + v5256;
        let v5258: f64 = v80 * v5253;
        let v5259: f64 = v5257 + v5258;
        let v5260: f64 = v54 * v5259;
        let v5261: f64 = v122 * v5244;
        let v5262: f64 = v2870 * v125;
        let v5263: f64 = v5261 - v5262;
        let v5264: f64 = v2876 * v122;
        let v5265: f64 = v125 * v5249;
        let v5266: f64 = v5264 + v5265;
        let v5267: f64 = v5263 - v5266;
        let v5268: f64 = v91 * v5267;
        let v5269: f64 = v138 * v5206;
        let v5270: f64 = v167 * v5210;
        let v5271: f64 = v5269 + v5270;
        let v5272: f64 = v94 * v5271;
        let v5273: f64 = v5268 + v5272;
        let v5274: f64 = v80 * v5273;
        let v5275: f64 = v2829 * v122;
        let v5276: f64 = v125 * v5217;
        let v5277: f64 = v5275 + v5276;
        let v5278: f64 = v122 * v5229;
        let v5279: f64 = v2842 * v125;
        let v5280: f64 = v5278 - v5279;
        let v5281: f64 = v5277 + v5280;
        let v5282: f64 = v139 * v5271;
        let v5283: f64 = v5281 - v5282;
        let v5284: f64 = v5274 - v5283;
        let v5285: f64 = v57 * v5284;
        let v5286: f64 = v5260 - v5285;
        let v5287: f64 = v23 * v5286;
        let v5288: f64 = v94 * v5232;
        let v5289: f64 = v91 * v5255;
        let v5290: f64 = v5288 - v5289;
        let v5291: f64 = v57 * v5273;
        let v5292: f64 = v54 * v5253;
        let v5293: f64 = v5291 - v5292;
        let v5294: f64 = v75 * v5293;
        let v5295: f64 = v5290 + v5294;
        let v5296: f64 = v25 * v5295;
        let v5297: f64 = v5287 - v5296;
        let v5298: f64 = v18 * v5293;
        let v5299: f64 = v5297 - v5298;
        let v5300: f64 = v2 * v5299;
        let v5301: f64 = v54 * v5273;
        let v5302: f64 = v57 * v5253;
        let v5303: f64 = v5301 + v5302;
        let v5304: f64 = v23 * v5303;
        let v5305: f64 = v94 * v5267;
        let v5306: f64 = v91 * v5271;
        let v5307: f64 = v5305 - v5306;
        let v5308: f64 = v25 * v5307;
        let v5309: f64 = v5304 - v5308;
        let v5310: f64 = v18 * v5309;
        let v5311: f64 = v75 * v5307;
        let v5312: f64 = v57 * v5259;
        let v5313: f64 = v54 * v5284;
        let v5314: f64 = v5312 + v5313;
        let v5315: f64 = v5311 - v5314;
        let v5316: f64 = v25 * v5303;
        let v5317: f64 = v23 * v5307;
        let v5318: f64 = v5316 + v5317;
        let v5319: f64 = v40 * v5318;
        let v5320: f64 = v5315 + v5319;
        let v5321: f64 = v5310 - v5320;
        let v5322: f64 = v4 * v5321;
        let v5323: f64 = v5300 - v5322;
        let v5324: f64 = v6 * v5323;
        let v5325: f64 = v25 * v5286;
        let v5326: f64 = v23 * v5295;
        let v5327: f64 = v5325 + v5326;
        let v5328: f64 = v40 * v5293;
        let v5329: f64 = v5327 + v5328;
        let v5330: f64 = v14 * v5329;
        let v5331: f64 = v5324 - v5330;
        let v5332: f64 = v5203 - v5331;
        let v5333: f64 = v0 * v5332;
        let v5334: f64 = v5333 * v2069;
        let v5335: f64 = v5199 + v5334;
        let v5336: f64 = v4760 * v1179;
        let v5337: f64 = v1495 * v2073;
        let v5338: f64 = v3585 + v3352;
        let v5339: f64 = v0 * v5338;
        let v5340: f64 = v5339 * v823;
        let v5341: f64 = v5337 + v5340;
        let v5342: f64 = v5336 - v5341;
        let v5343: f64 = v3549 * v25;
        let v5344: f64 = v3560 * v23;
        let v5345: f64 = v5343 + v5344;
        (
            v5150,
            v5159,
            v5179,
            v5185,
            v5193,
            v5195,
            v5197,
            v5203,
            v5240,
            v5283,
            v5290,
            v5299,
            v5315,
            v5321,
            v5329,
            v5331,
            v5333,
            v5335,
            v5337,
            v5342,
            v5345,
        )
    };
    let (
        v5351,
        v5355,
        v5361,
        v5363,
        v5367,
        v5437,
        v5467,
        v5469,
        v5482,
        v5494,
        v5498,
        v5517,
        v5519,
        v5522,
        v5523,
        v5534,
        v5541,
        v5543,
    ) = {
        let v5346: f64 = v18 * v5345;
        let v5347: f64 = v3549 * v23;
        let v5348: f64 = v3560 * v25;
        let v5349: f64 = v5347 - v5348;
        let v5350: f64 = v40 * v5349;
        let v5351: f64 = v5346 + v5350;
        let v5352: f64 = v4 * v5351;
        let v5353: f64 = v3522 * v25;
        let v5354: f64 = v3540 * v23;
        let v5355: f64 = v5353 + v5354;
        let v5356: f64 = v2 * v5355;
        let v5357: f64 = v5352 - v5356;
        let v5358: f64 = v6 * v5357;
        let v5359: f64 = v3522 * v23;
        let v5360: f64 = v3540 * v25;
        let v5361: f64 = v5359 - v5360;
        let v5362: f64 = v14 * v5361;
        let v5363: f64 = v5358 - v5362;
        let v5364: f64 = v5363 + v5363;
        let v5365: f64 = v0 * v5364;
        let v5366: f64 = v5365 * v1496;
        let v5367: f64 = v5342 - v5366;
        let v5368: f64 = v94 * v54;
        let v5369: f64 = v98 * v5368;
        let v5370: f64 = v91 * v54;
        let v5371: f64 = v92 * v5370;
        let v5372: f64 = v5369 - v5371;
        let v5373: f64 = v104 * v57;
        let v5374: f64 = v5372 - v5373;
        let v5375: f64 = v107 * v3370;
        let v5376: f64 = v94 * v3354;
        let v5377: f64 = v109 * v5376;
        let v5378: f64 = v5375 - v5377;
        let v5379: f64 = v5374 - v5378;
        let v5380: f64 = v125 * v5370;
        let v5381: f64 = v122 * v57;
        let v5382: f64 = v5380 - v5381;
        let v5383: f64 = v129 * v5382;
        let v5384: f64 = v125 * v57;
        let v5385: f64 = v122 * v5370;
        let v5386: f64 = v5384 + v5385;
        let v5387: f64 = v123 * v5386;
        let v5388: f64 = v5383 - v5387;
        let v5389: f64 = v135 * v5368;
        let v5390: f64 = v5388 - v5389;
        let v5391: f64 = v139 * v57;
        let v5392: f64 = v5376 + v5391;
        let v5393: f64 = v138 * v5392;
        let v5394: f64 = v139 * v5368;
        let v5395: f64 = v3370 + v5394;
        let v5396: f64 = v122 * v5395;
        let v5397: f64 = v91 * v3354;
        let v5398: f64 = v125 * v5397;
        let v5399: f64 = v5396 + v5398;
        let v5400: f64 = v143 * v5399;
        let v5401: f64 = v5393 + v5400;
        let v5402: f64 = v5390 + v5401;
        let v5403: f64 = v122 * v5402;
        let v5404: f64 = v157 * v5382;
        let v5405: f64 = v129 * v5386;
        let v5406: f64 = v5404 - v5405;
        let v5407: f64 = v160 * v5368;
        let v5408: f64 = v5406 - v5407;
        let v5409: f64 = v122 * v5397;
        let v5410: f64 = v125 * v5395;
        let v5411: f64 = v5409 - v5410;
        let v5412: f64 = v143 * v5411;
        let v5413: f64 = v167 * v5392;
        let v5414: f64 = v5412 - v5413;
        let v5415: f64 = v5408 + v5414;
        let v5416: f64 = v125 * v5415;
        let v5417: f64 = v5403 - v5416;
        let v5418: f64 = v5379 + v5417;
        let v5419: f64 = v91 * v5418;
        let v5420: f64 = v176 * v5368;
        let v5421: f64 = v98 * v5370;
        let v5422: f64 = v5420 - v5421;
        let v5423: f64 = v179 * v57;
        let v5424: f64 = v5422 - v5423;
        let v5425: f64 = v109 * v5397;
        let v5426: f64 = v183 * v3370;
        let v5427: f64 = v5425 + v5426;
        let v5428: f64 = v5424 + v5427;
        let v5429: f64 = v160 * v5382;
        let v5430: f64 = v135 * v5386;
        let v5431: f64 = v5429 - v5430;
        let v5432: f64 = v190 * v5368;
        let v5433: f64 = v5431 - v5432;
        let v5434: f64 = v167 * v5399;
        let v5435: f64 = v138 * v5411;
        let v5436: f64 = v5434 + v5435;
        let v5437: f64 = v5433 - v5436;
        let v5438: f64 = v5428 - v5437;
        let v5439: f64 = v198 * v5411;
        let v5440: f64 = v143 * v5382;
        let v5441: f64 = v138 * v5368;
        let v5442: f64 = v5440 + v5441;
        let v5443: f64 = v5439 + v5442;
        let v5444: f64 = v125 * v5443;
        let v5445: f64 = v198 * v5399;
        let v5446: f64 = v167 * v5368;
        let v5447: f64 = v143 * v5386;
        let v5448: f64 = v5446 - v5447;
        let v5449: f64 = v5445 + v5448;
        let v5450: f64 = v122 * v5449;
        let v5451: f64 = v5444 - v5450;
        let v5452: f64 = v139 * v5451;
        let v5453: f64 = v5438 - v5452;
        let v5454: f64 = v94 * v5453;
        let v5455: f64 = v5419 - v5454;
        let v5456: f64 = v55 * v54;
        let v5457: f64 = v5456 - v3496;
        let v5458: f64 = v3499 + v5457;
        let v5459: f64 = v5455 - v5458;
        let v5460: f64 = v3492 + v3491;
        let v5461: f64 = v224 * v3370;
        let v5462: f64 = v107 * v5370;
        let v5463: f64 = v183 * v5368;
        let v5464: f64 = v5462 + v5463;
        let v5465: f64 = v5461 + v5464;
        let v5466: f64 = v5451 - v5465;
        let v5467: f64 = v5460 - v5466;
        let v5468: f64 = v80 * v5467;
        let v5469: f64 = v5459 - v5468;
        let v5470: f64 = v54 * v5469;
        let v5471: f64 = v3466 * v57;
        let v5472: f64 = v5470 - v5471;
        let v5473: f64 = v3519 * v54;
        let v5474: f64 = v224 * v5397;
        let v5475: f64 = v109 * v5368;
        let v5476: f64 = v107 * v57;
        let v5477: f64 = v5475 + v5476;
        let v5478: f64 = v5474 + v5477;
        let v5479: f64 = v122 * v5443;
        let v5480: f64 = v125 * v5449;
        let v5481: f64 = v5479 + v5480;
        let v5482: f64 = v5478 + v5481;
        let v5483: f64 = v91 * v5482;
        let v5484: f64 = v109 * v5370;
        let v5485: f64 = v183 * v57;
        let v5486: f64 = v5484 - v5485;
        let v5487: f64 = v224 * v5376;
        let v5488: f64 = v5486 - v5487;
        let v5489: f64 = v198 * v5392;
        let v5490: f64 = v138 * v5386;
        let v5491: f64 = v167 * v5382;
        let v5492: f64 = v5490 + v5491;
        let v5493: f64 = v5489 - v5492;
        let v5494: f64 = v5488 - v5493;
        let v5495: f64 = v94 * v5494;
        let v5496: f64 = v5483 - v5495;
        let v5497: f64 = v3456 + v3455;
        let v5498: f64 = v5496 + v5497;
        let v5499: f64 = v80 * v5498;
        let v5500: f64 = v236 * v57;
        let v5501: f64 = v3358 - v5500;
        let v5502: f64 = v5501 - v3355;
        let v5503: f64 = v179 * v5368;
        let v5504: f64 = v104 * v5370;
        let v5505: f64 = v5503 - v5504;
        let v5506: f64 = v249 * v57;
        let v5507: f64 = v5505 - v5506;
        let v5508: f64 = v183 * v5376;
        let v5509: f64 = v107 * v5397;
        let v5510: f64 = v5508 + v5509;
        let v5511: f64 = v5507 - v5510;
        let v5512: f64 = v125 * v5402;
        let v5513: f64 = v122 * v5415;
        let v5514: f64 = v5512 + v5513;
        let v5515: f64 = v5511 + v5514;
        let v5516: f64 = v139 * v5493;
        let v5517: f64 = v5515 - v5516;
        let v5518: f64 = v5502 + v5517;
        let v5519: f64 = v5499 - v5518;
        let v5520: f64 = v57 * v5519;
        let v5521: f64 = v5473 + v5520;
        let v5522: f64 = v5472 - v5521;
        let v5523: f64 = v23 * v5522;
        let v5524: f64 = v217 * v3370;
        let v5525: f64 = v84 * v3354;
        let v5526: f64 = v5524 - v5525;
        let v5527: f64 = v67 * v54;
        let v5528: f64 = v239 * v57;
        let v5529: f64 = v5527 - v5528;
        let v5530: f64 = v5526 - v5529;
        let v5531: f64 = v94 * v5418;
        let v5532: f64 = v91 * v5453;
        let v5533: f64 = v5531 + v5532;
        let v5534: f64 = v5530 + v5533;
        let v5535: f64 = v3494 * v54;
        let v5536: f64 = v57 * v5498;
        let v5537: f64 = v5535 + v5536;
        let v5538: f64 = v54 * v5467;
        let v5539: f64 = v3464 * v57;
        let v5540: f64 = v5538 - v5539;
        let v5541: f64 = v5537 + v5540;
        let v5542: f64 = v75 * v5541;
        let v5543: f64 = v5534 + v5542;
        (
            v5351,
            v5355,
            v5361,
            v5363,
            v5367,
            v5437,
            v5467,
            v5469,
            v5482,
            v5494,
            v5498,
            v5517,
            v5519,
            v5522,
            v5523,
            v5534,
            v5541,
            v5543,
        )
    };
    let (
        v5547,
        v5575,
        v5581,
        v5589,
        v5591,
        v5600,
        v5604,
        v5610,
        v5612,
        v5616,
        v5658,
        v5676,
        v5692,
        v5699,
        v5701,
        v5702,
        v5709,
        v5722,
        v5725,
        v5739,
        v5740,
        v5741,
    ) = {
        let v5544: f64 = v25 * v5543;
        let v5545: f64 = v5523 - v5544;
        let v5546: f64 = v18 * v5541;
        let v5547: f64 = v5545 - v5546;
        let v5548: f64 = v2 * v5547;
        let v5549: f64 = v54 * v5498;
        let v5550: f64 = v3494 * v57;
        let v5551: f64 = v5549 - v5550;
        let v5552: f64 = v3464 * v54;
        let v5553: f64 = v57 * v5467;
        let v5554: f64 = v5552 + v5553;
        let v5555: f64 = v5551 - v5554;
        let v5556: f64 = v23 * v5555;
        let v5557: f64 = v94 * v5482;
        let v5558: f64 = v91 * v5494;
        let v5559: f64 = v5557 + v5558;
        let v5560: f64 = v217 * v57;
        let v5561: f64 = v84 * v54;
        let v5562: f64 = v5560 + v5561;
        let v5563: f64 = v5559 - v5562;
        let v5564: f64 = v25 * v5563;
        let v5565: f64 = v5556 - v5564;
        let v5566: f64 = v18 * v5565;
        let v5567: f64 = v75 * v5563;
        let v5568: f64 = v3466 * v54;
        let v5569: f64 = v57 * v5469;
        let v5570: f64 = v5568 + v5569;
        let v5571: f64 = v54 * v5519;
        let v5572: f64 = v3519 * v57;
        let v5573: f64 = v5571 - v5572;
        let v5574: f64 = v5570 + v5573;
        let v5575: f64 = v5567 - v5574;
        let v5576: f64 = v25 * v5555;
        let v5577: f64 = v23 * v5563;
        let v5578: f64 = v5576 + v5577;
        let v5579: f64 = v40 * v5578;
        let v5580: f64 = v5575 + v5579;
        let v5581: f64 = v5566 - v5580;
        let v5582: f64 = v4 * v5581;
        let v5583: f64 = v5548 - v5582;
        let v5584: f64 = v6 * v5583;
        let v5585: f64 = v25 * v5522;
        let v5586: f64 = v23 * v5543;
        let v5587: f64 = v5585 + v5586;
        let v5588: f64 = v40 * v5541;
        let v5589: f64 = v5587 + v5588;
        let v5590: f64 = v14 * v5589;
        let v5591: f64 = v5584 - v5590;
        let v5592: f64 = v3949 * v25;
        let v5593: f64 = v3953 * v23;
        let v5594: f64 = v5592 + v5593;
        let v5595: f64 = v18 * v5594;
        let v5596: f64 = v3949 * v23;
        let v5597: f64 = v3953 * v25;
        let v5598: f64 = v5596 - v5597;
        let v5599: f64 = v40 * v5598;
        let v5600: f64 = v5595 + v5599;
        let v5601: f64 = v4 * v5600;
        let v5602: f64 = v3931 * v25;
        let v5603: f64 = v3941 * v23;
        let v5604: f64 = v5602 + v5603;
        let v5605: f64 = v2 * v5604;
        let v5606: f64 = v5601 - v5605;
        let v5607: f64 = v6 * v5606;
        let v5608: f64 = v3931 * v23;
        let v5609: f64 = v3941 * v25;
        let v5610: f64 = v5608 - v5609;
        let v5611: f64 = v14 * v5610;
        let v5612: f64 = v5607 - v5611;
        let v5613: f64 = v5591 + v5612;
        let v5614: f64 = v0 * v5613;
        let v5615: f64 = v5614 * v1748;
        let v5616: f64 = v5367 - v5615;
        let v5617: f64 = v57 * v91;
        let v5618: f64 = v98 * v5617;
        let v5619: f64 = v57 * v94;
        let v5620: f64 = v92 * v5619;
        let v5621: f64 = v5618 + v5620;
        let v5622: f64 = v3370 * v91;
        let v5623: f64 = v5622 - v3393;
        let v5624: f64 = v109 * v5623;
        let v5625: f64 = v5621 - v5624;
        let v5626: f64 = v122 * v5619;
        let v5627: f64 = v123 * v5626;
        let v5628: f64 = v125 * v5619;
        let v5629: f64 = v129 * v5628;
        let v5630: f64 = v5627 - v5629;
        let v5631: f64 = v135 * v5617;
        let v5632: f64 = v5630 - v5631;
        let v5633: f64 = v138 * v5623;
        let v5634: f64 = v139 * v5617;
        let v5635: f64 = v122 * v5634;
        let v5636: f64 = v3370 * v94;
        let v5637: f64 = v3369 + v5636;
        let v5638: f64 = v125 * v5637;
        let v5639: f64 = v5635 + v5638;
        let v5640: f64 = v143 * v5639;
        let v5641: f64 = v5633 - v5640;
        let v5642: f64 = v5632 - v5641;
        let v5643: f64 = v122 * v5642;
        let v5644: f64 = v129 * v5626;
        let v5645: f64 = v157 * v5628;
        let v5646: f64 = v5644 - v5645;
        let v5647: f64 = v160 * v5617;
        let v5648: f64 = v5646 - v5647;
        let v5649: f64 = v122 * v5637;
        let v5650: f64 = v125 * v5634;
        let v5651: f64 = v5649 - v5650;
        let v5652: f64 = v143 * v5651;
        let v5653: f64 = v167 * v5623;
        let v5654: f64 = v5652 + v5653;
        let v5655: f64 = v5648 + v5654;
        let v5656: f64 = v125 * v5655;
        let v5657: f64 = v5643 - v5656;
        let v5658: f64 = v5625 + v5657;
        let v5659: f64 = v91 * v5658;
        let v5660: f64 = v3416 * v94;
        let v5661: f64 = v5659 - v5660;
        let v5662: f64 = v3451 * v91;
        let v5663: f64 = v176 * v5617;
        let v5664: f64 = v98 * v5619;
        let v5665: f64 = v5663 + v5664;
        let v5666: f64 = v109 * v5637;
        let v5667: f64 = v5665 + v5666;
        let v5668: f64 = v135 * v5626;
        let v5669: f64 = v160 * v5628;
        let v5670: f64 = v5668 - v5669;
        let v5671: f64 = v190 * v5617;
        let v5672: f64 = v5670 - v5671;
        let v5673: f64 = v167 * v5639;
        let v5674: f64 = v138 * v5651;
        let v5675: f64 = v5673 + v5674;
        let v5676: f64 = v5672 - v5675;
        let v5677: f64 = v5667 - v5676;
        let v5678: f64 = v198 * v5651;
        let v5679: f64 = v138 * v5617;
        let v5680: f64 = v143 * v5628;
        let v5681: f64 = v5679 - v5680;
        let v5682: f64 = v5678 + v5681;
        let v5683: f64 = v125 * v5682;
        let v5684: f64 = v198 * v5639;
        let v5685: f64 = v167 * v5617;
        let v5686: f64 = v143 * v5626;
        let v5687: f64 = v5685 + v5686;
        let v5688: f64 = v5684 + v5687;
        let v5689: f64 = v122 * v5688;
        let v5690: f64 = v5683 - v5689;
        let v5691: f64 = v139 * v5690;
        let v5692: f64 = v5677 - v5691;
        let v5693: f64 = v94 * v5692;
        let v5694: f64 = v5662 + v5693;
        let v5695: f64 = v5661 - v5694;
        let v5696: f64 = v183 * v5617;
        let v5697: f64 = v107 * v5619;
        let v5698: f64 = v5696 - v5697;
        let v5699: f64 = v5690 - v5698;
        let v5700: f64 = v80 * v5699;
        let v5701: f64 = v5695 + v5700;
        let v5702: f64 = v54 * v5701;
        let v5703: f64 = v224 * v5637;
        let v5704: f64 = v109 * v5617;
        let v5705: f64 = v5703 + v5704;
        let v5706: f64 = v122 * v5682;
        let v5707: f64 = v125 * v5688;
        let v5708: f64 = v5706 + v5707;
        let v5709: f64 = v5705 + v5708;
        let v5710: f64 = v91 * v5709;
        let v5711: f64 = v3476 * v94;
        let v5712: f64 = v5710 - v5711;
        let v5713: f64 = v3488 * v91;
        let v5714: f64 = v224 * v5623;
        let v5715: f64 = v109 * v5619;
        let v5716: f64 = v5714 - v5715;
        let v5717: f64 = v138 * v5626;
        let v5718: f64 = v167 * v5628;
        let v5719: f64 = v5717 + v5718;
        let v5720: f64 = v198 * v5623;
        let v5721: f64 = v5719 - v5720;
        let v5722: f64 = v5716 - v5721;
        let v5723: f64 = v94 * v5722;
        let v5724: f64 = v5713 + v5723;
        let v5725: f64 = v5712 - v5724;
        let v5726: f64 = v80 * v5725;
        let v5727: f64 = v179 * v5617;
        let v5728: f64 = v104 * v5619;
        let v5729: f64 = v5727 + v5728;
        let v5730: f64 = v183 * v5623;
        let v5731: f64 = v107 * v5637;
        let v5732: f64 = v5730 - v5731;
        let v5733: f64 = v5729 + v5732;
        let v5734: f64 = v125 * v5642;
        let v5735: f64 = v122 * v5655;
        let v5736: f64 = v5734 + v5735;
        let v5737: f64 = v5733 + v5736;
        let v5738: f64 = v139 * v5721;
        let v5739: f64 = v5737 - v5738;
        let v5740: f64 = v5726 - v5739;
        let v5741: f64 = v57 * v5740;
        (
            v5547,
            v5575,
            v5581,
            v5589,
            v5591,
            v5600,
            v5604,
            v5610,
            v5612,
            v5616,
            v5658,
            v5676,
            v5692,
            v5699,
            v5701,
            v5702,
            v5709,
            v5722,
            v5725,
            v5739,
            v5740,
            v5741,
        )
    };
    let (
        v5750,
        v5759,
        v5779,
        v5785,
        v5793,
        v5795,
        v5804,
        v5808,
        v5814,
        v5816,
        v5820,
        v5823,
        v5833,
        v5839,
        v5841,
        v5878,
        v5891,
        v5897,
        v5905,
        v5909,
        v5921,
        v5922,
        v5924,
        v5928,
        v5931,
        v5933,
        v5937,
        v5938,
        v5939,
    ) = {
        let v5742: f64 = v5702 - v5741;
        let v5743: f64 = v23 * v5742;
        let v5744: f64 = v3416 * v91;
        let v5745: f64 = v94 * v5658;
        let v5746: f64 = v5744 + v5745;
        let v5747: f64 = v91 * v5692;
        let v5748: f64 = v3451 * v94;
        let v5749: f64 = v5747 - v5748;
        let v5750: f64 = v5746 + v5749;
        let v5751: f64 = v57 * v5725;
        let v5752: f64 = v54 * v5699;
        let v5753: f64 = v5751 - v5752;
        let v5754: f64 = v75 * v5753;
        let v5755: f64 = v5750 + v5754;
        let v5756: f64 = v25 * v5755;
        let v5757: f64 = v5743 - v5756;
        let v5758: f64 = v18 * v5753;
        let v5759: f64 = v5757 - v5758;
        let v5760: f64 = v2 * v5759;
        let v5761: f64 = v54 * v5725;
        let v5762: f64 = v57 * v5699;
        let v5763: f64 = v5761 + v5762;
        let v5764: f64 = v23 * v5763;
        let v5765: f64 = v3476 * v91;
        let v5766: f64 = v94 * v5709;
        let v5767: f64 = v5765 + v5766;
        let v5768: f64 = v91 * v5722;
        let v5769: f64 = v3488 * v94;
        let v5770: f64 = v5768 - v5769;
        let v5771: f64 = v5767 + v5770;
        let v5772: f64 = v25 * v5771;
        let v5773: f64 = v5764 - v5772;
        let v5774: f64 = v18 * v5773;
        let v5775: f64 = v75 * v5771;
        let v5776: f64 = v57 * v5701;
        let v5777: f64 = v54 * v5740;
        let v5778: f64 = v5776 + v5777;
        let v5779: f64 = v5775 - v5778;
        let v5780: f64 = v25 * v5763;
        let v5781: f64 = v23 * v5771;
        let v5782: f64 = v5780 + v5781;
        let v5783: f64 = v40 * v5782;
        let v5784: f64 = v5779 + v5783;
        let v5785: f64 = v5774 - v5784;
        let v5786: f64 = v4 * v5785;
        let v5787: f64 = v5760 - v5786;
        let v5788: f64 = v6 * v5787;
        let v5789: f64 = v25 * v5742;
        let v5790: f64 = v23 * v5755;
        let v5791: f64 = v5789 + v5790;
        let v5792: f64 = v40 * v5753;
        let v5793: f64 = v5791 + v5792;
        let v5794: f64 = v14 * v5793;
        let v5795: f64 = v5788 - v5794;
        let v5796: f64 = v4237 * v25;
        let v5797: f64 = v4241 * v23;
        let v5798: f64 = v5796 + v5797;
        let v5799: f64 = v18 * v5798;
        let v5800: f64 = v4237 * v23;
        let v5801: f64 = v4241 * v25;
        let v5802: f64 = v5800 - v5801;
        let v5803: f64 = v40 * v5802;
        let v5804: f64 = v5799 + v5803;
        let v5805: f64 = v4 * v5804;
        let v5806: f64 = v4220 * v25;
        let v5807: f64 = v4229 * v23;
        let v5808: f64 = v5806 + v5807;
        let v5809: f64 = v2 * v5808;
        let v5810: f64 = v5805 - v5809;
        let v5811: f64 = v6 * v5810;
        let v5812: f64 = v4220 * v23;
        let v5813: f64 = v4229 * v25;
        let v5814: f64 = v5812 - v5813;
        let v5815: f64 = v14 * v5814;
        let v5816: f64 = v5811 - v5815;
        let v5817: f64 = v5795 + v5816;
        let v5818: f64 = v0 * v5817;
        let v5819: f64 = v5818 * v1937;
        let v5820: f64 = v5616 - v5819;
        let v5821: f64 = v4422 * v25;
        let v5822: f64 = v4431 * v23;
        let v5823: f64 = v5821 + v5822;
        let v5824: f64 = v2 * v5823;
        let v5825: f64 = v4440 * v23;
        let v5826: f64 = v4445 * v25;
        let v5827: f64 = v5825 - v5826;
        let v5828: f64 = v18 * v5827;
        let v5829: f64 = v4445 * v23;
        let v5830: f64 = v4440 * v25;
        let v5831: f64 = v5829 + v5830;
        let v5832: f64 = v40 * v5831;
        let v5833: f64 = v5828 - v5832;
        let v5834: f64 = v4 * v5833;
        let v5835: f64 = v5824 + v5834;
        let v5836: f64 = v6 * v5835;
        let v5837: f64 = v4422 * v23;
        let v5838: f64 = v4431 * v25;
        let v5839: f64 = v5837 - v5838;
        let v5840: f64 = v14 * v5839;
        let v5841: f64 = v5836 + v5840;
        let v5842: f64 = v54 * v122;
        let v5843: f64 = v3363 * v125;
        let v5844: f64 = v5842 + v5843;
        let v5845: f64 = v123 * v5844;
        let v5846: f64 = v3363 * v122;
        let v5847: f64 = v54 * v125;
        let v5848: f64 = v5846 - v5847;
        let v5849: f64 = v129 * v5848;
        let v5850: f64 = v5845 + v5849;
        let v5851: f64 = v3395 * v122;
        let v5852: f64 = v3391 * v125;
        let v5853: f64 = v5851 - v5852;
        let v5854: f64 = v143 * v5853;
        let v5855: f64 = v5850 + v5854;
        let v5856: f64 = v122 * v5855;
        let v5857: f64 = v3400 * v125;
        let v5858: f64 = v5856 - v5857;
        let v5859: f64 = v3413 * v122;
        let v5860: f64 = v129 * v5844;
        let v5861: f64 = v157 * v5848;
        let v5862: f64 = v5860 + v5861;
        let v5863: f64 = v3395 * v125;
        let v5864: f64 = v3391 * v122;
        let v5865: f64 = v5863 + v5864;
        let v5866: f64 = v143 * v5865;
        let v5867: f64 = v5862 - v5866;
        let v5868: f64 = v125 * v5867;
        let v5869: f64 = v5859 + v5868;
        let v5870: f64 = v5858 - v5869;
        let v5871: f64 = v91 * v5870;
        let v5872: f64 = v135 * v5844;
        let v5873: f64 = v160 * v5848;
        let v5874: f64 = v5872 + v5873;
        let v5875: f64 = v167 * v5853;
        let v5876: f64 = v138 * v5865;
        let v5877: f64 = v5875 - v5876;
        let v5878: f64 = v5874 - v5877;
        let v5879: f64 = v3441 * v122;
        let v5880: f64 = v143 * v5848;
        let v5881: f64 = v198 * v5865;
        let v5882: f64 = v5880 - v5881;
        let v5883: f64 = v125 * v5882;
        let v5884: f64 = v5879 + v5883;
        let v5885: f64 = v198 * v5853;
        let v5886: f64 = v143 * v5844;
        let v5887: f64 = v5885 + v5886;
        let v5888: f64 = v122 * v5887;
        let v5889: f64 = v3447 * v125;
        let v5890: f64 = v5888 - v5889;
        let v5891: f64 = v5884 - v5890;
        let v5892: f64 = v139 * v5891;
        let v5893: f64 = v5878 + v5892;
        let v5894: f64 = v94 * v5893;
        let v5895: f64 = v5871 + v5894;
        let v5896: f64 = v80 * v5891;
        let v5897: f64 = v5895 + v5896;
        let v5898: f64 = v54 * v5897;
        let v5899: f64 = v122 * v5882;
        let v5900: f64 = v3441 * v125;
        let v5901: f64 = v5899 - v5900;
        let v5902: f64 = v3447 * v122;
        let v5903: f64 = v125 * v5887;
        let v5904: f64 = v5902 + v5903;
        let v5905: f64 = v5901 + v5904;
        let v5906: f64 = v91 * v5905;
        let v5907: f64 = v138 * v5844;
        let v5908: f64 = v167 * v5848;
        let v5909: f64 = v5907 - v5908;
        let v5910: f64 = v94 * v5909;
        let v5911: f64 = v5906 + v5910;
        let v5912: f64 = v80 * v5911;
        let v5913: f64 = v3400 * v122;
        let v5914: f64 = v125 * v5855;
        let v5915: f64 = v5913 + v5914;
        let v5916: f64 = v122 * v5867;
        let v5917: f64 = v3413 * v125;
        let v5918: f64 = v5916 - v5917;
        let v5919: f64 = v5915 + v5918;
        let v5920: f64 = v139 * v5909;
        let v5921: f64 = v5919 - v5920;
        let v5922: f64 = v5912 - v5921;
        let v5923: f64 = v57 * v5922;
        let v5924: f64 = v5898 - v5923;
        let v5925: f64 = v23 * v5924;
        let v5926: f64 = v94 * v5870;
        let v5927: f64 = v91 * v5893;
        let v5928: f64 = v5926 - v5927;
        let v5929: f64 = v57 * v5911;
        let v5930: f64 = v54 * v5891;
        let v5931: f64 = v5929 - v5930;
        let v5932: f64 = v75 * v5931;
        let v5933: f64 = v5928 + v5932;
        let v5934: f64 = v25 * v5933;
        let v5935: f64 = v5925 - v5934;
        let v5936: f64 = v18 * v5931;
        let v5937: f64 = v5935 - v5936;
        let v5938: f64 = v2 * v5937;
        let v5939: f64 = v54 * v5911;
        (
            v5750,
            v5759,
            v5779,
            v5785,
            v5793,
            v5795,
            v5804,
            v5808,
            v5814,
            v5816,
            v5820,
            v5823,
            v5833,
            v5839,
            v5841,
            v5878,
            v5891,
            v5897,
            v5905,
            v5909,
            v5921,
            v5922,
            v5924,
            v5928,
            v5931,
            v5933,
            v5937,
            v5938,
            v5939,
        )
    };
    let (
        v5953,
        v5959,
        v5967,
        v5969,
        v5971,
        v5973,
        v5975,
        v5996,
        v6000,
        v6009,
        v6017,
        v6019,
        v6023,
        v6035,
        v6046,
        v6048,
        v6056,
        v6058,
        v6071,
        v6080,
        v6083,
        v6098,
        v6114,
        v6121,
        v6123,
        v6124,
        v6128,
        v6131,
        v6132,
        v6135,
        v6136,
        v6137,
    ) = {
        let v5940: f64 = v57 * v5891;
        let v5941: f64 = v5939 + v5940;
        let v5942: f64 = v23 * v5941;
        let v5943: f64 = v94 * v5905;
        let v5944: f64 = v91 * v5909;
        let v5945: f64 = v5943 - v5944;
        let v5946: f64 = v25 * v5945;
        let v5947: f64 = v5942 - v5946;
        let v5948: f64 = v18 * v5947;
        let v5949: f64 = v75 * v5945;
        let v5950: f64 = v57 * v5897;
        let v5951: f64 = v54 * v5922;
        let v5952: f64 = v5950 + v5951;
        let v5953: f64 = v5949 - v5952;
        let v5954: f64 = v25 * v5941;
        let v5955: f64 = v23 * v5945;
        let v5956: f64 = v5954 + v5955;
        let v5957: f64 = v40 * v5956;
        let v5958: f64 = v5953 + v5957;
        let v5959: f64 = v5948 - v5958;
        let v5960: f64 = v4 * v5959;
        let v5961: f64 = v5938 - v5960;
        let v5962: f64 = v6 * v5961;
        let v5963: f64 = v25 * v5924;
        let v5964: f64 = v23 * v5933;
        let v5965: f64 = v5963 + v5964;
        let v5966: f64 = v40 * v5931;
        let v5967: f64 = v5965 + v5966;
        let v5968: f64 = v14 * v5967;
        let v5969: f64 = v5962 - v5968;
        let v5970: f64 = v5841 - v5969;
        let v5971: f64 = v0 * v5970;
        let v5972: f64 = v5971 * v2069;
        let v5973: f64 = v5820 + v5972;
        let v5974: f64 = v5008 * v1179;
        let v5975: f64 = v1747 * v2073;
        let v5976: f64 = v3977 + v3837;
        let v5977: f64 = v0 * v5976;
        let v5978: f64 = v5977 * v823;
        let v5979: f64 = v5975 + v5978;
        let v5980: f64 = v5974 - v5979;
        let v5981: f64 = v5612 + v5591;
        let v5982: f64 = v0 * v5981;
        let v5983: f64 = v5982 * v1496;
        let v5984: f64 = v5980 - v5983;
        let v5985: f64 = v3902 * v57;
        let v5986: f64 = v3929 * v54;
        let v5987: f64 = v5985 + v5986;
        let v5988: f64 = v23 * v5987;
        let v5989: f64 = v3927 * v54;
        let v5990: f64 = v3900 * v57;
        let v5991: f64 = v5989 - v5990;
        let v5992: f64 = v75 * v5991;
        let v5993: f64 = v25 * v5992;
        let v5994: f64 = v5988 + v5993;
        let v5995: f64 = v18 * v5991;
        let v5996: f64 = v5994 + v5995;
        let v5997: f64 = v2 * v5996;
        let v5998: f64 = v3902 * v54;
        let v5999: f64 = v3929 * v57;
        let v6000: f64 = v5998 - v5999;
        let v6001: f64 = v3927 * v57;
        let v6002: f64 = v3900 * v54;
        let v6003: f64 = v6001 + v6002;
        let v6004: f64 = v25 * v6003;
        let v6005: f64 = v40 * v6004;
        let v6006: f64 = v6000 + v6005;
        let v6007: f64 = v23 * v6003;
        let v6008: f64 = v18 * v6007;
        let v6009: f64 = v6006 - v6008;
        let v6010: f64 = v4 * v6009;
        let v6011: f64 = v5997 + v6010;
        let v6012: f64 = v6 * v6011;
        let v6013: f64 = v23 * v5992;
        let v6014: f64 = v25 * v5987;
        let v6015: f64 = v6013 - v6014;
        let v6016: f64 = v40 * v5991;
        let v6017: f64 = v6015 + v6016;
        let v6018: f64 = v14 * v6017;
        let v6019: f64 = v6012 + v6018;
        let v6020: f64 = v6019 + v6019;
        let v6021: f64 = v0 * v6020;
        let v6022: f64 = v6021 * v1748;
        let v6023: f64 = v5984 + v6022;
        let v6024: f64 = v4196 * v57;
        let v6025: f64 = v4218 * v54;
        let v6026: f64 = v6024 + v6025;
        let v6027: f64 = v23 * v6026;
        let v6028: f64 = v4210 * v54;
        let v6029: f64 = v4190 * v57;
        let v6030: f64 = v6028 + v6029;
        let v6031: f64 = v75 * v6030;
        let v6032: f64 = v25 * v6031;
        let v6033: f64 = v6027 + v6032;
        let v6034: f64 = v18 * v6030;
        let v6035: f64 = v6033 + v6034;
        let v6036: f64 = v2 * v6035;
        let v6037: f64 = v4190 * v54;
        let v6038: f64 = v4210 * v57;
        let v6039: f64 = v6037 - v6038;
        let v6040: f64 = v23 * v6039;
        let v6041: f64 = v18 * v6040;
        let v6042: f64 = v25 * v6039;
        let v6043: f64 = v40 * v6042;
        let v6044: f64 = v4196 * v54;
        let v6045: f64 = v4218 * v57;
        let v6046: f64 = v6044 - v6045;
        let v6047: f64 = v6043 - v6046;
        let v6048: f64 = v6041 - v6047;
        let v6049: f64 = v4 * v6048;
        let v6050: f64 = v6036 + v6049;
        let v6051: f64 = v6 * v6050;
        let v6052: f64 = v23 * v6031;
        let v6053: f64 = v25 * v6026;
        let v6054: f64 = v6052 - v6053;
        let v6055: f64 = v40 * v6030;
        let v6056: f64 = v6054 + v6055;
        let v6057: f64 = v14 * v6056;
        let v6058: f64 = v6051 + v6057;
        let v6059: f64 = v92 * v91;
        let v6060: f64 = v6059 - v3865;
        let v6061: f64 = v122 * v91;
        let v6062: f64 = v123 * v6061;
        let v6063: f64 = v125 * v91;
        let v6064: f64 = v129 * v6063;
        let v6065: f64 = v6062 - v6064;
        let v6066: f64 = v135 * v94;
        let v6067: f64 = v6065 + v6066;
        let v6068: f64 = v139 * v94;
        let v6069: f64 = v122 * v6068;
        let v6070: f64 = v143 * v6069;
        let v6071: f64 = v6067 - v6070;
        let v6072: f64 = v122 * v6071;
        let v6073: f64 = v129 * v6061;
        let v6074: f64 = v157 * v6063;
        let v6075: f64 = v6073 - v6074;
        let v6076: f64 = v160 * v94;
        let v6077: f64 = v6075 + v6076;
        let v6078: f64 = v125 * v6068;
        let v6079: f64 = v143 * v6078;
        let v6080: f64 = v6077 + v6079;
        let v6081: f64 = v125 * v6080;
        let v6082: f64 = v6072 - v6081;
        let v6083: f64 = v6060 + v6082;
        let v6084: f64 = v91 * v6083;
        let v6085: f64 = v3863 * v94;
        let v6086: f64 = v6084 - v6085;
        let v6087: f64 = v3892 * v91;
        let v6088: f64 = v176 * v94;
        let v6089: f64 = v3839 - v6088;
        let v6090: f64 = v135 * v6061;
        let v6091: f64 = v160 * v6063;
        let v6092: f64 = v6090 - v6091;
        let v6093: f64 = v190 * v94;
        let v6094: f64 = v6092 + v6093;
        let v6095: f64 = v167 * v6069;
        let v6096: f64 = v138 * v6078;
        let v6097: f64 = v6095 - v6096;
        let v6098: f64 = v6094 + v6097;
        let v6099: f64 = v6089 - v6098;
        let v6100: f64 = v198 * v6078;
        let v6101: f64 = v138 * v94;
        let v6102: f64 = v143 * v6063;
        let v6103: f64 = v6101 + v6102;
        let v6104: f64 = v6100 - v6103;
        let v6105: f64 = v125 * v6104;
        let v6106: f64 = v143 * v6061;
        let v6107: f64 = v167 * v94;
        let v6108: f64 = v6106 - v6107;
        let v6109: f64 = v198 * v6069;
        let v6110: f64 = v6108 - v6109;
        let v6111: f64 = v122 * v6110;
        let v6112: f64 = v6105 - v6111;
        let v6113: f64 = v139 * v6112;
        let v6114: f64 = v6099 - v6113;
        let v6115: f64 = v94 * v6114;
        let v6116: f64 = v6087 + v6115;
        let v6117: f64 = v6086 - v6116;
        let v6118: f64 = v107 * v91;
        let v6119: f64 = v183 * v94;
        let v6120: f64 = v6118 + v6119;
        let v6121: f64 = v6120 + v6112;
        let v6122: f64 = v80 * v6121;
        let v6123: f64 = v6117 + v6122;
        let v6124: f64 = v54 * v6123;
        let v6125: f64 = v122 * v6104;
        let v6126: f64 = v125 * v6110;
        let v6127: f64 = v6125 + v6126;
        let v6128: f64 = v6127 - v3923;
        let v6129: f64 = v91 * v6128;
        let v6130: f64 = v3921 * v94;
        let v6131: f64 = v6129 - v6130;
        let v6132: f64 = v3924 * v91;
        let v6133: f64 = v138 * v6061;
        let v6134: f64 = v167 * v6063;
        let v6135: f64 = v6133 + v6134;
        let v6136: f64 = v3917 + v6135;
        let v6137: f64 = v94 * v6136;
        (
            v5953,
            v5959,
            v5967,
            v5969,
            v5971,
            v5973,
            v5975,
            v5996,
            v6000,
            v6009,
            v6017,
            v6019,
            v6023,
            v6035,
            v6046,
            v6048,
            v6056,
            v6058,
            v6071,
            v6080,
            v6083,
            v6098,
            v6114,
            v6121,
            v6123,
            v6124,
            v6128,
            v6131,
            v6132,
            v6135,
            v6136,
            v6137,
        )
    };
    let (
        v6149,
        v6160,
        v6169,
        v6189,
        v6195,
        v6203,
        v6205,
        v6207,
        v6209,
        v6220,
        v6281,
        v6292,
        v6297,
        v6313,
        v6319,
        v6327,
        v6329,
        v6332,
        v6333,
        v6334,
        v6335,
    ) = {
        let v6138: f64 = v6132 + v6137;
        let v6139: f64 = v6131 + v6138;
        let v6140: f64 = v80 * v6139;
        let v6141: f64 = v104 * v91;
        let v6142: f64 = v179 * v94;
        let v6143: f64 = v6141 - v6142;
        let v6144: f64 = v125 * v6071;
        let v6145: f64 = v122 * v6080;
        let v6146: f64 = v6144 + v6145;
        let v6147: f64 = v6143 + v6146;
        let v6148: f64 = v139 * v6135;
        let v6149: f64 = v6147 - v6148;
        let v6150: f64 = v6140 - v6149;
        let v6151: f64 = v57 * v6150;
        let v6152: f64 = v6124 - v6151;
        let v6153: f64 = v23 * v6152;
        let v6154: f64 = v3863 * v91;
        let v6155: f64 = v94 * v6083;
        let v6156: f64 = v6154 + v6155;
        let v6157: f64 = v91 * v6114;
        let v6158: f64 = v3892 * v94;
        let v6159: f64 = v6157 - v6158;
        let v6160: f64 = v6156 + v6159;
        let v6161: f64 = v57 * v6139;
        let v6162: f64 = v54 * v6121;
        let v6163: f64 = v6161 - v6162;
        let v6164: f64 = v75 * v6163;
        let v6165: f64 = v6160 + v6164;
        let v6166: f64 = v25 * v6165;
        let v6167: f64 = v6153 - v6166;
        let v6168: f64 = v18 * v6163;
        let v6169: f64 = v6167 - v6168;
        let v6170: f64 = v2 * v6169;
        let v6171: f64 = v54 * v6139;
        let v6172: f64 = v57 * v6121;
        let v6173: f64 = v6171 + v6172;
        let v6174: f64 = v23 * v6173;
        let v6175: f64 = v3921 * v91;
        let v6176: f64 = v94 * v6128;
        let v6177: f64 = v6175 + v6176;
        let v6178: f64 = v91 * v6136;
        let v6179: f64 = v3924 * v94;
        let v6180: f64 = v6178 - v6179;
        let v6181: f64 = v6177 - v6180;
        let v6182: f64 = v25 * v6181;
        let v6183: f64 = v6174 - v6182;
        let v6184: f64 = v18 * v6183;
        let v6185: f64 = v75 * v6181;
        let v6186: f64 = v57 * v6123;
        let v6187: f64 = v54 * v6150;
        let v6188: f64 = v6186 + v6187;
        let v6189: f64 = v6185 - v6188;
        let v6190: f64 = v25 * v6173;
        let v6191: f64 = v23 * v6181;
        let v6192: f64 = v6190 + v6191;
        let v6193: f64 = v40 * v6192;
        let v6194: f64 = v6189 + v6193;
        let v6195: f64 = v6184 - v6194;
        let v6196: f64 = v4 * v6195;
        let v6197: f64 = v6170 - v6196;
        let v6198: f64 = v6 * v6197;
        let v6199: f64 = v25 * v6152;
        let v6200: f64 = v23 * v6165;
        let v6201: f64 = v6199 + v6200;
        let v6202: f64 = v40 * v6163;
        let v6203: f64 = v6201 + v6202;
        let v6204: f64 = v14 * v6203;
        let v6205: f64 = v6198 - v6204;
        let v6206: f64 = v6058 - v6205;
        let v6207: f64 = v0 * v6206;
        let v6208: f64 = v6207 * v1937;
        let v6209: f64 = v6023 + v6208;
        let v6210: f64 = v3848 * v122;
        let v6211: f64 = v138 * v6210;
        let v6212: f64 = v3848 * v125;
        let v6213: f64 = v167 * v6212;
        let v6214: f64 = v6211 + v6213;
        let v6215: f64 = v94 * v125;
        let v6216: f64 = v135 * v6215;
        let v6217: f64 = v94 * v122;
        let v6218: f64 = v160 * v6217;
        let v6219: f64 = v6216 + v6218;
        let v6220: f64 = v6214 - v6219;
        let v6221: f64 = v3882 * v122;
        let v6222: f64 = v143 * v6217;
        let v6223: f64 = v198 * v6210;
        let v6224: f64 = v6222 + v6223;
        let v6225: f64 = v125 * v6224;
        let v6226: f64 = v6221 - v6225;
        let v6227: f64 = v3888 * v125;
        let v6228: f64 = v198 * v6212;
        let v6229: f64 = v143 * v6215;
        let v6230: f64 = v6228 + v6229;
        let v6231: f64 = v122 * v6230;
        let v6232: f64 = v6227 + v6231;
        let v6233: f64 = v6226 + v6232;
        let v6234: f64 = v139 * v6233;
        let v6235: f64 = v6220 + v6234;
        let v6236: f64 = v94 * v6235;
        let v6237: f64 = v3851 * v125;
        let v6238: f64 = v123 * v6215;
        let v6239: f64 = v129 * v6217;
        let v6240: f64 = v6238 + v6239;
        let v6241: f64 = v143 * v6212;
        let v6242: f64 = v6240 + v6241;
        let v6243: f64 = v122 * v6242;
        let v6244: f64 = v6237 + v6243;
        let v6245: f64 = v3860 * v122;
        let v6246: f64 = v129 * v6215;
        let v6247: f64 = v157 * v6217;
        let v6248: f64 = v6246 + v6247;
        let v6249: f64 = v143 * v6210;
        let v6250: f64 = v6248 + v6249;
        let v6251: f64 = v125 * v6250;
        let v6252: f64 = v6245 - v6251;
        let v6253: f64 = v6244 + v6252;
        let v6254: f64 = v91 * v6253;
        let v6255: f64 = v6236 - v6254;
        let v6256: f64 = v80 * v6233;
        let v6257: f64 = v6255 + v6256;
        let v6258: f64 = v54 * v6257;
        let v6259: f64 = v3888 * v122;
        let v6260: f64 = v125 * v6230;
        let v6261: f64 = v6259 - v6260;
        let v6262: f64 = v3882 * v125;
        let v6263: f64 = v122 * v6224;
        let v6264: f64 = v6262 + v6263;
        let v6265: f64 = v6261 - v6264;
        let v6266: f64 = v91 * v6265;
        let v6267: f64 = v167 * v6217;
        let v6268: f64 = v138 * v6215;
        let v6269: f64 = v6267 - v6268;
        let v6270: f64 = v94 * v6269;
        let v6271: f64 = v6266 + v6270;
        let v6272: f64 = v80 * v6271;
        let v6273: f64 = v3851 * v122;
        let v6274: f64 = v125 * v6242;
        let v6275: f64 = v6273 - v6274;
        let v6276: f64 = v3860 * v125;
        let v6277: f64 = v122 * v6250;
        let v6278: f64 = v6276 + v6277;
        let v6279: f64 = v6275 - v6278;
        let v6280: f64 = v139 * v6269;
        let v6281: f64 = v6279 - v6280;
        let v6282: f64 = v6272 - v6281;
        let v6283: f64 = v57 * v6282;
        let v6284: f64 = v6258 - v6283;
        let v6285: f64 = v23 * v6284;
        let v6286: f64 = v57 * v6271;
        let v6287: f64 = v54 * v6233;
        let v6288: f64 = v6286 - v6287;
        let v6289: f64 = v75 * v6288;
        let v6290: f64 = v94 * v6253;
        let v6291: f64 = v91 * v6235;
        let v6292: f64 = v6290 + v6291;
        let v6293: f64 = v6289 - v6292;
        let v6294: f64 = v25 * v6293;
        let v6295: f64 = v6285 - v6294;
        let v6296: f64 = v18 * v6288;
        let v6297: f64 = v6295 - v6296;
        let v6298: f64 = v2 * v6297;
        let v6299: f64 = v54 * v6271;
        let v6300: f64 = v57 * v6233;
        let v6301: f64 = v6299 + v6300;
        let v6302: f64 = v23 * v6301;
        let v6303: f64 = v94 * v6265;
        let v6304: f64 = v91 * v6269;
        let v6305: f64 = v6303 - v6304;
        let v6306: f64 = v25 * v6305;
        let v6307: f64 = v6302 - v6306;
        let v6308: f64 = v18 * v6307;
        let v6309: f64 = v75 * v6305;
        let v6310: f64 = v57 * v6257;
        let v6311: f64 = v54 * v6282;
        let v6312: f64 = v6310 + v6311;
        let v6313: f64 = v6309 - v6312;
        let v6314: f64 = v25 * v6301;
        let v6315: f64 = v23 * v6305;
        let v6316: f64 = v6314 + v6315;
        let v6317: f64 = v40 * v6316;
        let v6318: f64 = v6313 + v6317;
        let v6319: f64 = v6308 - v6318;
        let v6320: f64 = v4 * v6319;
        let v6321: f64 = v6298 - v6320;
        let v6322: f64 = v6 * v6321;
        let v6323: f64 = v25 * v6284;
        let v6324: f64 = v23 * v6293;
        let v6325: f64 = v6323 + v6324;
        let v6326: f64 = v40 * v6288;
        let v6327: f64 = v6325 + v6326;
        let v6328: f64 = v14 * v6327;
        let v6329: f64 = v6322 - v6328;
        let v6330: f64 = v4420 * v54;
        let v6331: f64 = v4410 * v57;
        let v6332: f64 = v6330 - v6331;
        let v6333: f64 = v23 * v6332;
        let v6334: f64 = v4418 * v54;
        let v6335: f64 = v4404 * v57;
        (
            v6149,
            v6160,
            v6169,
            v6189,
            v6195,
            v6203,
            v6205,
            v6207,
            v6209,
            v6220,
            v6281,
            v6292,
            v6297,
            v6313,
            v6319,
            v6327,
            v6329,
            v6332,
            v6333,
            v6334,
            v6335,
        )
    };
    let (
        v6341,
        v6345,
        v6354,
        v6362,
        v6364,
        v6368,
        v6370,
        v6395,
        v6402,
        v6416,
        v6422,
        v6430,
        v6432,
        v6436,
        v6451,
        v6470,
        v6471,
        v6484,
        v6491,
        v6500,
        v6516,
        v6522,
        v6530,
        v6532,
        v6533,
    ) = {
        let v6336: f64 = v6334 - v6335;
        let v6337: f64 = v75 * v6336;
        let v6338: f64 = v25 * v6337;
        let v6339: f64 = v6333 + v6338;
        let v6340: f64 = v18 * v6336;
        let v6341: f64 = v6339 + v6340;
        let v6342: f64 = v2 * v6341;
        let v6343: f64 = v4410 * v54;
        let v6344: f64 = v4420 * v57;
        let v6345: f64 = v6343 + v6344;
        let v6346: f64 = v4404 * v54;
        let v6347: f64 = v4418 * v57;
        let v6348: f64 = v6346 + v6347;
        let v6349: f64 = v25 * v6348;
        let v6350: f64 = v40 * v6349;
        let v6351: f64 = v6345 - v6350;
        let v6352: f64 = v23 * v6348;
        let v6353: f64 = v18 * v6352;
        let v6354: f64 = v6351 + v6353;
        let v6355: f64 = v4 * v6354;
        let v6356: f64 = v6342 - v6355;
        let v6357: f64 = v6 * v6356;
        let v6358: f64 = v25 * v6332;
        let v6359: f64 = v23 * v6337;
        let v6360: f64 = v6358 - v6359;
        let v6361: f64 = v40 * v6336;
        let v6362: f64 = v6360 - v6361;
        let v6363: f64 = v14 * v6362;
        let v6364: f64 = v6357 - v6363;
        let v6365: f64 = v6329 + v6364;
        let v6366: f64 = v0 * v6365;
        let v6367: f64 = v6366 * v2069;
        let v6368: f64 = v6209 - v6367;
        let v6369: f64 = v5197 * v1179;
        let v6370: f64 = v1936 * v2073;
        let v6371: f64 = v4265 + v4166;
        let v6372: f64 = v0 * v6371;
        let v6373: f64 = v6372 * v823;
        let v6374: f64 = v6370 + v6373;
        let v6375: f64 = v6369 - v6374;
        let v6376: f64 = v5816 + v5795;
        let v6377: f64 = v0 * v6376;
        let v6378: f64 = v6377 * v1496;
        let v6379: f64 = v6375 - v6378;
        let v6380: f64 = v6207 * v1748;
        let v6381: f64 = v6379 + v6380;
        let v6382: f64 = v4201 * v94;
        let v6383: f64 = v4208 * v91;
        let v6384: f64 = v6382 + v6383;
        let v6385: f64 = v80 * v6384;
        let v6386: f64 = v57 * v6385;
        let v6387: f64 = v4180 * v94;
        let v6388: f64 = v4192 * v91;
        let v6389: f64 = v6387 + v6388;
        let v6390: f64 = v54 * v6389;
        let v6391: f64 = v6386 - v6390;
        let v6392: f64 = v23 * v6391;
        let v6393: f64 = v4180 * v91;
        let v6394: f64 = v4192 * v94;
        let v6395: f64 = v6393 - v6394;
        let v6396: f64 = v57 * v6384;
        let v6397: f64 = v75 * v6396;
        let v6398: f64 = v6395 - v6397;
        let v6399: f64 = v25 * v6398;
        let v6400: f64 = v6392 - v6399;
        let v6401: f64 = v18 * v6396;
        let v6402: f64 = v6400 + v6401;
        let v6403: f64 = v2 * v6402;
        let v6404: f64 = v54 * v6384;
        let v6405: f64 = v23 * v6404;
        let v6406: f64 = v4201 * v91;
        let v6407: f64 = v4208 * v94;
        let v6408: f64 = v6406 - v6407;
        let v6409: f64 = v25 * v6408;
        let v6410: f64 = v6405 + v6409;
        let v6411: f64 = v18 * v6410;
        let v6412: f64 = v75 * v6408;
        let v6413: f64 = v57 * v6389;
        let v6414: f64 = v54 * v6385;
        let v6415: f64 = v6413 + v6414;
        let v6416: f64 = v6412 + v6415;
        let v6417: f64 = v23 * v6408;
        let v6418: f64 = v25 * v6404;
        let v6419: f64 = v6417 - v6418;
        let v6420: f64 = v40 * v6419;
        let v6421: f64 = v6416 + v6420;
        let v6422: f64 = v6411 + v6421;
        let v6423: f64 = v4 * v6422;
        let v6424: f64 = v6403 + v6423;
        let v6425: f64 = v6 * v6424;
        let v6426: f64 = v25 * v6391;
        let v6427: f64 = v23 * v6398;
        let v6428: f64 = v6426 + v6427;
        let v6429: f64 = v40 * v6396;
        let v6430: f64 = v6428 - v6429;
        let v6431: f64 = v14 * v6430;
        let v6432: f64 = v6425 - v6431;
        let v6433: f64 = v6432 + v6432;
        let v6434: f64 = v0 * v6433;
        let v6435: f64 = v6434 * v1937;
        let v6436: f64 = v6381 - v6435;
        let v6437: f64 = v123 * v122;
        let v6438: f64 = v6437 - v4173;
        let v6439: f64 = v122 * v6438;
        let v6440: f64 = v4171 * v125;
        let v6441: f64 = v6439 - v6440;
        let v6442: f64 = v4177 * v122;
        let v6443: f64 = v157 * v125;
        let v6444: f64 = v4168 - v6443;
        let v6445: f64 = v125 * v6444;
        let v6446: f64 = v6442 + v6445;
        let v6447: f64 = v6441 - v6446;
        let v6448: f64 = v91 * v6447;
        let v6449: f64 = v135 * v122;
        let v6450: f64 = v160 * v125;
        let v6451: f64 = v6449 - v6450;
        let v6452: f64 = v4186 * v122;
        let v6453: f64 = v6452 - v4199;
        let v6454: f64 = v4188 * v125;
        let v6455: f64 = v4198 - v6454;
        let v6456: f64 = v6453 - v6455;
        let v6457: f64 = v139 * v6456;
        let v6458: f64 = v6451 + v6457;
        let v6459: f64 = v94 * v6458;
        let v6460: f64 = v6448 + v6459;
        let v6461: f64 = v80 * v6456;
        let v6462: f64 = v6460 + v6461;
        let v6463: f64 = v54 * v6462;
        let v6464: f64 = v4188 * v122;
        let v6465: f64 = v6464 + v4187;
        let v6466: f64 = v4186 * v125;
        let v6467: f64 = v6466 + v4189;
        let v6468: f64 = v6465 - v6467;
        let v6469: f64 = v91 * v6468;
        let v6470: f64 = v138 * v122;
        let v6471: f64 = v167 * v125;
        let v6472: f64 = v6470 + v6471;
        let v6473: f64 = v94 * v6472;
        let v6474: f64 = v6469 + v6473;
        let v6475: f64 = v80 * v6474;
        let v6476: f64 = v4171 * v122;
        let v6477: f64 = v125 * v6438;
        let v6478: f64 = v6476 + v6477;
        let v6479: f64 = v122 * v6444;
        let v6480: f64 = v4177 * v125;
        let v6481: f64 = v6479 - v6480;
        let v6482: f64 = v6478 + v6481;
        let v6483: f64 = v139 * v6472;
        let v6484: f64 = v6482 - v6483;
        let v6485: f64 = v6475 - v6484;
        let v6486: f64 = v57 * v6485;
        let v6487: f64 = v6463 - v6486;
        let v6488: f64 = v23 * v6487;
        let v6489: f64 = v94 * v6447;
        let v6490: f64 = v91 * v6458;
        let v6491: f64 = v6489 - v6490;
        let v6492: f64 = v57 * v6474;
        let v6493: f64 = v54 * v6456;
        let v6494: f64 = v6492 - v6493;
        let v6495: f64 = v75 * v6494;
        let v6496: f64 = v6491 + v6495;
        let v6497: f64 = v25 * v6496;
        let v6498: f64 = v6488 - v6497;
        let v6499: f64 = v18 * v6494;
        let v6500: f64 = v6498 - v6499;
        let v6501: f64 = v2 * v6500;
        let v6502: f64 = v54 * v6474;
        let v6503: f64 = v57 * v6456;
        let v6504: f64 = v6502 + v6503;
        let v6505: f64 = v23 * v6504;
        let v6506: f64 = v94 * v6468;
        let v6507: f64 = v91 * v6472;
        let v6508: f64 = v6506 - v6507;
        let v6509: f64 = v25 * v6508;
        let v6510: f64 = v6505 - v6509;
        let v6511: f64 = v18 * v6510;
        let v6512: f64 = v75 * v6508;
        let v6513: f64 = v57 * v6462;
        let v6514: f64 = v54 * v6485;
        let v6515: f64 = v6513 + v6514;
        let v6516: f64 = v6512 - v6515;
        let v6517: f64 = v25 * v6504;
        let v6518: f64 = v23 * v6508;
        let v6519: f64 = v6517 + v6518;
        let v6520: f64 = v40 * v6519;
        let v6521: f64 = v6516 + v6520;
        let v6522: f64 = v6511 - v6521;
        let v6523: f64 = v4 * v6522;
        let v6524: f64 = v6501 - v6523;
        let v6525: f64 = v6 * v6524;
        let v6526: f64 = v25 * v6487;
        let v6527: f64 = v23 * v6496;
        let v6528: f64 = v6526 + v6527;
        let v6529: f64 = v40 * v6494;
        let v6530: f64 = v6528 + v6529;
        let v6531: f64 = v14 * v6530;
        let v6532: f64 = v6525 - v6531;
        let v6533: f64 = v4406 * v91;
        (
            v6341,
            v6345,
            v6354,
            v6362,
            v6364,
            v6368,
            v6370,
            v6395,
            v6402,
            v6416,
            v6422,
            v6430,
            v6432,
            v6436,
            v6451,
            v6470,
            v6471,
            v6484,
            v6491,
            v6500,
            v6516,
            v6522,
            v6530,
            v6532,
            v6533,
        )
    };
    let (
        v6544,
        v6551,
        v6558,
        v6569,
        v6577,
        v6579,
        v6583,
        v6585,
        v6618,
        v6627,
        v6634,
        v6647,
        v6655,
        v6657,
        v6661,
        v6668,
        v6675,
        v6682,
        v6689,
        v6696,
        v6700,
        v6718,
        v6724,
        v6726,
        v6730,
        v6731,
    ) = {
        let v6534: f64 = v4400 * v94;
        let v6535: f64 = v6533 - v6534;
        let v6536: f64 = v54 * v6535;
        let v6537: f64 = v4417 * v94;
        let v6538: f64 = v80 * v6537;
        let v6539: f64 = v57 * v6538;
        let v6540: f64 = v6536 - v6539;
        let v6541: f64 = v23 * v6540;
        let v6542: f64 = v4400 * v91;
        let v6543: f64 = v4406 * v94;
        let v6544: f64 = v6542 + v6543;
        let v6545: f64 = v57 * v6537;
        let v6546: f64 = v75 * v6545;
        let v6547: f64 = v6544 + v6546;
        let v6548: f64 = v25 * v6547;
        let v6549: f64 = v6541 - v6548;
        let v6550: f64 = v18 * v6545;
        let v6551: f64 = v6549 - v6550;
        let v6552: f64 = v2 * v6551;
        let v6553: f64 = v57 * v6535;
        let v6554: f64 = v54 * v6538;
        let v6555: f64 = v6553 + v6554;
        let v6556: f64 = v4417 * v91;
        let v6557: f64 = v75 * v6556;
        let v6558: f64 = v6555 + v6557;
        let v6559: f64 = v54 * v6537;
        let v6560: f64 = v25 * v6559;
        let v6561: f64 = v23 * v6556;
        let v6562: f64 = v6560 - v6561;
        let v6563: f64 = v40 * v6562;
        let v6564: f64 = v6558 - v6563;
        let v6565: f64 = v23 * v6559;
        let v6566: f64 = v25 * v6556;
        let v6567: f64 = v6565 + v6566;
        let v6568: f64 = v18 * v6567;
        let v6569: f64 = v6564 + v6568;
        let v6570: f64 = v4 * v6569;
        let v6571: f64 = v6552 - v6570;
        let v6572: f64 = v6 * v6571;
        let v6573: f64 = v25 * v6540;
        let v6574: f64 = v23 * v6547;
        let v6575: f64 = v6573 + v6574;
        let v6576: f64 = v40 * v6545;
        let v6577: f64 = v6575 + v6576;
        let v6578: f64 = v14 * v6577;
        let v6579: f64 = v6572 - v6578;
        let v6580: f64 = v6532 + v6579;
        let v6581: f64 = v0 * v6580;
        let v6582: f64 = v6581 * v2069;
        let v6583: f64 = v6436 - v6582;
        let v6584: f64 = v5333 * v1179;
        let v6585: f64 = v2068 * v2073;
        let v6586: f64 = v4465 + v4397;
        let v6587: f64 = v0 * v6586;
        let v6588: f64 = v6587 * v823;
        let v6589: f64 = v6585 + v6588;
        let v6590: f64 = v6584 - v6589;
        let v6591: f64 = v5971 * v1496;
        let v6592: f64 = v6590 + v6591;
        let v6593: f64 = v6364 + v6329;
        let v6594: f64 = v0 * v6593;
        let v6595: f64 = v6594 * v1748;
        let v6596: f64 = v6592 - v6595;
        let v6597: f64 = v6579 + v6532;
        let v6598: f64 = v0 * v6597;
        let v6599: f64 = v6598 * v1937;
        let v6600: f64 = v6596 - v6599;
        let v6601: f64 = v4204 - v4203;
        let v6602: f64 = v91 * v6601;
        let v6603: f64 = v80 * v6602;
        let v6604: f64 = v6451 + v6603;
        let v6605: f64 = v57 * v6604;
        let v6606: f64 = v91 * v4184;
        let v6607: f64 = v6471 + v6470;
        let v6608: f64 = v139 * v6607;
        let v6609: f64 = v94 * v6608;
        let v6610: f64 = v6606 + v6609;
        let v6611: f64 = v80 * v6607;
        let v6612: f64 = v6610 + v6611;
        let v6613: f64 = v54 * v6612;
        let v6614: f64 = v6605 - v6613;
        let v6615: f64 = v23 * v6614;
        let v6616: f64 = v91 * v6608;
        let v6617: f64 = v94 * v4184;
        let v6618: f64 = v6616 - v6617;
        let v6619: f64 = v57 * v6602;
        let v6620: f64 = v54 * v6607;
        let v6621: f64 = v6619 - v6620;
        let v6622: f64 = v75 * v6621;
        let v6623: f64 = v6618 - v6622;
        let v6624: f64 = v25 * v6623;
        let v6625: f64 = v6615 - v6624;
        let v6626: f64 = v18 * v6621;
        let v6627: f64 = v6625 + v6626;
        let v6628: f64 = v2 * v6627;
        let v6629: f64 = v94 * v6601;
        let v6630: f64 = v75 * v6629;
        let v6631: f64 = v57 * v6612;
        let v6632: f64 = v54 * v6604;
        let v6633: f64 = v6631 + v6632;
        let v6634: f64 = v6630 - v6633;
        let v6635: f64 = v57 * v6607;
        let v6636: f64 = v54 * v6602;
        let v6637: f64 = v6635 + v6636;
        let v6638: f64 = v25 * v6637;
        let v6639: f64 = v23 * v6629;
        let v6640: f64 = v6638 + v6639;
        let v6641: f64 = v40 * v6640;
        let v6642: f64 = v6634 + v6641;
        let v6643: f64 = v25 * v6629;
        let v6644: f64 = v23 * v6637;
        let v6645: f64 = v6643 - v6644;
        let v6646: f64 = v18 * v6645;
        let v6647: f64 = v6642 + v6646;
        let v6648: f64 = v4 * v6647;
        let v6649: f64 = v6628 - v6648;
        let v6650: f64 = v6 * v6649;
        let v6651: f64 = v25 * v6614;
        let v6652: f64 = v23 * v6623;
        let v6653: f64 = v6651 + v6652;
        let v6654: f64 = v40 * v6621;
        let v6655: f64 = v6653 - v6654;
        let v6656: f64 = v14 * v6655;
        let v6657: f64 = v6650 - v6656;
        let v6658: f64 = v6657 + v6657;
        let v6659: f64 = v0 * v6658;
        let v6660: f64 = v6659 * v2069;
        let v6661: f64 = v6600 - v6660;
        let v6662: f64 = v349 * v2;
        let v6663: f64 = v4 * v1095;
        let v6664: f64 = v6662 + v6663;
        let v6665: f64 = v2 * v1158;
        let v6666: f64 = v417 * v4;
        let v6667: f64 = v6665 - v6666;
        let v6668: f64 = v6664 + v6667;
        let v6669: f64 = v6668 - v798;
        let v6670: f64 = v0 * v6669;
        let v6671: f64 = v6670 * v1179;
        let v6672: f64 = v2074 + v6671;
        let v6673: f64 = v4 * v1428;
        let v6674: f64 = v2 * v1480;
        let v6675: f64 = v6673 + v6674;
        let v6676: f64 = v6675 - v739;
        let v6677: f64 = v0 * v6676;
        let v6678: f64 = v6677 * v1496;
        let v6679: f64 = v6672 + v6678;
        let v6680: f64 = v4 * v1702;
        let v6681: f64 = v2 * v1736;
        let v6682: f64 = v6680 + v6681;
        let v6683: f64 = v6682 - v684;
        let v6684: f64 = v0 * v6683;
        let v6685: f64 = v6684 * v1748;
        let v6686: f64 = v6679 + v6685;
        let v6687: f64 = v4 * v1899;
        let v6688: f64 = v2 * v1925;
        let v6689: f64 = v6687 + v6688;
        let v6690: f64 = v6689 - v631;
        let v6691: f64 = v0 * v6690;
        let v6692: f64 = v6691 * v1937;
        let v6693: f64 = v6686 + v6692;
        let v6694: f64 = v4 * v2035;
        let v6695: f64 = v2 * v2057;
        let v6696: f64 = v6694 + v6695;
        let v6697: f64 = v6696 - v568;
        let v6698: f64 = v0 * v6697;
        let v6699: f64 = v6698 * v2069;
        let v6700: f64 = v6693 + v6699;
        let v6701: f64 = v4 * v707;
        let v6702: f64 = v2 * v771;
        let v6703: f64 = v6701 + v6702;
        let v6704: f64 = v2075 * v14;
        let v6705: f64 = v2409 * v6;
        let v6706: f64 = v6704 - v6705;
        let v6707: f64 = v6703 - v6706;
        let v6708: f64 = v6707 + v2425;
        let v6709: f64 = v0 * v6708;
        let v6710: f64 = v6709 * v2073;
        let v6711: f64 = v2344 * v2;
        let v6712: f64 = v4 * v2691;
        let v6713: f64 = v6711 + v6712;
        let v6714: f64 = v2 * v2749;
        let v6715: f64 = v2404 * v4;
        let v6716: f64 = v6714 - v6715;
        let v6717: f64 = v6713 + v6716;
        let v6718: f64 = v0 * v6717;
        let v6719: f64 = v6718 * v1179;
        let v6720: f64 = v6710 + v6719;
        let v6721: f64 = v4 * v3286;
        let v6722: f64 = v2 * v3338;
        let v6723: f64 = v6721 + v6722;
        let v6724: f64 = v0 * v6723;
        let v6725: f64 = v6724 * v1496;
        let v6726: f64 = v6720 + v6725;
        let v6727: f64 = v4 * v3793;
        let v6728: f64 = v2 * v3827;
        let v6729: f64 = v6727 + v6728;
        let v6730: f64 = v0 * v6729;
        let v6731: f64 = v6730 * v1748;
        (
            v6544,
            v6551,
            v6558,
            v6569,
            v6577,
            v6579,
            v6583,
            v6585,
            v6618,
            v6627,
            v6634,
            v6647,
            v6655,
            v6657,
            v6661,
            v6668,
            v6675,
            v6682,
            v6689,
            v6696,
            v6700,
            v6718,
            v6724,
            v6726,
            v6730,
            v6731,
        )
    };
    let (
        v6744,
        v6748,
        v6752,
        v6759,
        v6762,
        v6769,
        v6772,
        v6779,
        v6782,
        v6789,
        v6792,
        v6796,
        v6800,
        v6808,
        v6815,
        v6818,
        v6825,
        v6828,
        v6835,
        v6838,
        v6842,
        v6846,
        v6856,
        v6863,
        v6866,
        v6873,
        v6876,
        v6880,
        v6884,
        v6898,
        v6905,
        v6908,
        v6912,
        v6916,
        v6929,
    ) = {
        let v6732: f64 = v6726 + v6731;
        let v6733: f64 = v4 * v4130;
        let v6734: f64 = v2 * v4156;
        let v6735: f64 = v6733 + v6734;
        let v6736: f64 = v0 * v6735;
        let v6737: f64 = v6736 * v1937;
        let v6738: f64 = v6732 + v6737;
        let v6739: f64 = v4 * v4365;
        let v6740: f64 = v2 * v4387;
        let v6741: f64 = v6739 + v6740;
        let v6742: f64 = v0 * v6741;
        let v6743: f64 = v6742 * v2069;
        let v6744: f64 = v6738 + v6743;
        let v6745: f64 = v6668 + v3039;
        let v6746: f64 = v0 * v6745;
        let v6747: f64 = v6746 * v2073;
        let v6748: f64 = v6718 * v823;
        let v6749: f64 = v6747 + v6748;
        let v6750: f64 = v2992 * v2;
        let v6751: f64 = v3028 * v4;
        let v6752: f64 = v6750 - v6751;
        let v6753: f64 = v6752 + v6752;
        let v6754: f64 = v0 * v6753;
        let v6755: f64 = v6754 * v1179;
        let v6756: f64 = v6749 + v6755;
        let v6757: f64 = v4 * v4704;
        let v6758: f64 = v2 * v4744;
        let v6759: f64 = v6757 + v6758;
        let v6760: f64 = v3544 * v2;
        let v6761: f64 = v3575 * v4;
        let v6762: f64 = v6760 - v6761;
        let v6763: f64 = v6759 + v6762;
        let v6764: f64 = v0 * v6763;
        let v6765: f64 = v6764 * v1496;
        let v6766: f64 = v6756 + v6765;
        let v6767: f64 = v4 * v4962;
        let v6768: f64 = v2 * v4996;
        let v6769: f64 = v6767 + v6768;
        let v6770: f64 = v3945 * v2;
        let v6771: f64 = v3967 * v4;
        let v6772: f64 = v6770 - v6771;
        let v6773: f64 = v6769 + v6772;
        let v6774: f64 = v0 * v6773;
        let v6775: f64 = v6774 * v1748;
        let v6776: f64 = v6766 + v6775;
        let v6777: f64 = v4 * v5159;
        let v6778: f64 = v2 * v5185;
        let v6779: f64 = v6777 + v6778;
        let v6780: f64 = v4233 * v2;
        let v6781: f64 = v4255 * v4;
        let v6782: f64 = v6780 - v6781;
        let v6783: f64 = v6779 + v6782;
        let v6784: f64 = v0 * v6783;
        let v6785: f64 = v6784 * v1937;
        let v6786: f64 = v6776 + v6785;
        let v6787: f64 = v4 * v5299;
        let v6788: f64 = v2 * v5321;
        let v6789: f64 = v6787 + v6788;
        let v6790: f64 = v4435 * v2;
        let v6791: f64 = v4455 * v4;
        let v6792: f64 = v6790 - v6791;
        let v6793: f64 = v6789 + v6792;
        let v6794: f64 = v0 * v6793;
        let v6795: f64 = v6794 * v2069;
        let v6796: f64 = v6786 + v6795;
        let v6797: f64 = v6675 + v3585;
        let v6798: f64 = v0 * v6797;
        let v6799: f64 = v6798 * v2073;
        let v6800: f64 = v6724 * v823;
        let v6801: f64 = v6799 + v6800;
        let v6802: f64 = v6762 + v6759;
        let v6803: f64 = v0 * v6802;
        let v6804: f64 = v6803 * v1179;
        let v6805: f64 = v6801 + v6804;
        let v6806: f64 = v4 * v5355;
        let v6807: f64 = v2 * v5351;
        let v6808: f64 = v6806 + v6807;
        let v6809: f64 = v6808 + v6808;
        let v6810: f64 = v0 * v6809;
        let v6811: f64 = v6810 * v1496;
        let v6812: f64 = v6805 - v6811;
        let v6813: f64 = v4 * v5547;
        let v6814: f64 = v2 * v5581;
        let v6815: f64 = v6813 + v6814;
        let v6816: f64 = v4 * v5604;
        let v6817: f64 = v2 * v5600;
        let v6818: f64 = v6816 + v6817;
        let v6819: f64 = v6815 - v6818;
        let v6820: f64 = v0 * v6819;
        let v6821: f64 = v6820 * v1748;
        let v6822: f64 = v6812 + v6821;
        let v6823: f64 = v4 * v5759;
        let v6824: f64 = v2 * v5785;
        let v6825: f64 = v6823 + v6824;
        let v6826: f64 = v4 * v5808;
        let v6827: f64 = v2 * v5804;
        let v6828: f64 = v6826 + v6827;
        let v6829: f64 = v6825 - v6828;
        let v6830: f64 = v0 * v6829;
        let v6831: f64 = v6830 * v1937;
        let v6832: f64 = v6822 + v6831;
        let v6833: f64 = v4 * v5937;
        let v6834: f64 = v2 * v5959;
        let v6835: f64 = v6833 + v6834;
        let v6836: f64 = v2 * v5833;
        let v6837: f64 = v4 * v5823;
        let v6838: f64 = v6836 - v6837;
        let v6839: f64 = v6835 + v6838;
        let v6840: f64 = v0 * v6839;
        let v6841: f64 = v6840 * v2069;
        let v6842: f64 = v6832 + v6841;
        let v6843: f64 = v6682 + v3977;
        let v6844: f64 = v0 * v6843;
        let v6845: f64 = v6844 * v2073;
        let v6846: f64 = v6730 * v823;
        let v6847: f64 = v6845 + v6846;
        let v6848: f64 = v6772 + v6769;
        let v6849: f64 = v0 * v6848;
        let v6850: f64 = v6849 * v1179;
        let v6851: f64 = v6847 + v6850;
        let v6852: f64 = v6820 * v1496;
        let v6853: f64 = v6851 + v6852;
        let v6854: f64 = v2 * v6009;
        let v6855: f64 = v4 * v5996;
        let v6856: f64 = v6854 - v6855;
        let v6857: f64 = v6856 + v6856;
        let v6858: f64 = v0 * v6857;
        let v6859: f64 = v6858 * v1748;
        let v6860: f64 = v6853 + v6859;
        let v6861: f64 = v4 * v6169;
        let v6862: f64 = v2 * v6195;
        let v6863: f64 = v6861 + v6862;
        let v6864: f64 = v2 * v6048;
        let v6865: f64 = v4 * v6035;
        let v6866: f64 = v6864 - v6865;
        let v6867: f64 = v6863 + v6866;
        let v6868: f64 = v0 * v6867;
        let v6869: f64 = v6868 * v1937;
        let v6870: f64 = v6860 + v6869;
        let v6871: f64 = v4 * v6297;
        let v6872: f64 = v2 * v6319;
        let v6873: f64 = v6871 + v6872;
        let v6874: f64 = v4 * v6341;
        let v6875: f64 = v2 * v6354;
        let v6876: f64 = v6874 + v6875;
        let v6877: f64 = v6873 + v6876;
        let v6878: f64 = v0 * v6877;
        let v6879: f64 = v6878 * v2069;
        let v6880: f64 = v6870 + v6879;
        let v6881: f64 = v6689 + v4265;
        let v6882: f64 = v0 * v6881;
        let v6883: f64 = v6882 * v2073;
        let v6884: f64 = v6736 * v823;
        let v6885: f64 = v6883 + v6884;
        let v6886: f64 = v6782 + v6779;
        let v6887: f64 = v0 * v6886;
        let v6888: f64 = v6887 * v1179;
        let v6889: f64 = v6885 + v6888;
        let v6890: f64 = v6830 * v1496;
        let v6891: f64 = v6889 + v6890;
        let v6892: f64 = v6866 + v6863;
        let v6893: f64 = v0 * v6892;
        let v6894: f64 = v6893 * v1748;
        let v6895: f64 = v6891 + v6894;
        let v6896: f64 = v4 * v6402;
        let v6897: f64 = v2 * v6422;
        let v6898: f64 = v6896 - v6897;
        let v6899: f64 = v6898 + v6898;
        let v6900: f64 = v0 * v6899;
        let v6901: f64 = v6900 * v1937;
        let v6902: f64 = v6895 + v6901;
        let v6903: f64 = v4 * v6500;
        let v6904: f64 = v2 * v6522;
        let v6905: f64 = v6903 + v6904;
        let v6906: f64 = v4 * v6551;
        let v6907: f64 = v2 * v6569;
        let v6908: f64 = v6906 + v6907;
        let v6909: f64 = v6905 + v6908;
        let v6910: f64 = v0 * v6909;
        let v6911: f64 = v6910 * v2069;
        let v6912: f64 = v6902 + v6911;
        let v6913: f64 = v6696 + v4465;
        let v6914: f64 = v0 * v6913;
        let v6915: f64 = v6914 * v2073;
        let v6916: f64 = v6742 * v823;
        let v6917: f64 = v6915 + v6916;
        let v6918: f64 = v6792 + v6789;
        let v6919: f64 = v0 * v6918;
        let v6920: f64 = v6919 * v1179;
        let v6921: f64 = v6917 + v6920;
        let v6922: f64 = v6838 + v6835;
        let v6923: f64 = v0 * v6922;
        let v6924: f64 = v6923 * v1496;
        let v6925: f64 = v6921 + v6924;
        let v6926: f64 = v6876 + v6873;
        let v6927: f64 = v0 * v6926;
        let v6928: f64 = v6927 * v1748;
        let v6929: f64 = v6925 + v6928;
        (
            v6744,
            v6748,
            v6752,
            v6759,
            v6762,
            v6769,
            v6772,
            v6779,
            v6782,
            v6789,
            v6792,
            v6796,
            v6800,
            v6808,
            v6815,
            v6818,
            v6825,
            v6828,
            v6835,
            v6838,
            v6842,
            v6846,
            v6856,
            v6863,
            v6866,
            v6873,
            v6876,
            v6880,
            v6884,
            v6898,
            v6905,
            v6908,
            v6912,
            v6916,
            v6929,
        )
    };
    let (
        v6936,
        v6940,
        v6960,
        v6980,
        v6999,
        v7007,
        v7024,
        v7032,
        v7049,
        v7057,
        v7074,
        v7082,
        v7099,
        v7119,
        v7127,
    ) = {
        let v6930: f64 = v6908 + v6905;
        let v6931: f64 = v0 * v6930;
        let v6932: f64 = v6931 * v1937;
        let v6933: f64 = v6929 + v6932;
        let v6934: f64 = v4 * v6627;
        let v6935: f64 = v2 * v6647;
        let v6936: f64 = v6934 + v6935;
        let v6937: f64 = v6936 + v6936;
        let v6938: f64 = v0 * v6937;
        let v6939: f64 = v6938 * v2069;
        let v6940: f64 = v6933 + v6939;
        let v6941: f64 = v798 - v6668;
        let v6942: f64 = v0 * v6941;
        let v6943: f64 = v6942 * v823;
        let v6944: f64 = v4478 + v6943;
        let v6945: f64 = v1492 - v1128;
        let v6946: f64 = v0 * v6945;
        let v6947: f64 = v6946 * v1496;
        let v6948: f64 = v6944 + v6947;
        let v6949: f64 = v1744 - v1074;
        let v6950: f64 = v0 * v6949;
        let v6951: f64 = v6950 * v1748;
        let v6952: f64 = v6948 + v6951;
        let v6953: f64 = v1933 - v1021;
        let v6954: f64 = v0 * v6953;
        let v6955: f64 = v6954 * v1937;
        let v6956: f64 = v6952 + v6955;
        let v6957: f64 = v2065 - v958;
        let v6958: f64 = v0 * v6957;
        let v6959: f64 = v6958 * v2069;
        let v6960: f64 = v6956 + v6959;
        let v6961: f64 = v798 + v2768;
        let v6962: f64 = v0 * v6961;
        let v6963: f64 = v6962 * v2073;
        let v6964: f64 = v6963 - v6748;
        let v6965: f64 = v3350 - v2722;
        let v6966: f64 = v0 * v6965;
        let v6967: f64 = v6966 * v1496;
        let v6968: f64 = v6964 + v6967;
        let v6969: f64 = v3835 - v2673;
        let v6970: f64 = v0 * v6969;
        let v6971: f64 = v6970 * v1748;
        let v6972: f64 = v6968 + v6971;
        let v6973: f64 = v4164 - v2620;
        let v6974: f64 = v0 * v6973;
        let v6975: f64 = v6974 * v1937;
        let v6976: f64 = v6972 + v6975;
        let v6977: f64 = v4395 - v2557;
        let v6978: f64 = v0 * v6977;
        let v6979: f64 = v6978 * v2069;
        let v6980: f64 = v6976 + v6979;
        let v6981: f64 = v1175 - v4474;
        let v6982: f64 = v0 * v6981;
        let v6983: f64 = v6982 * v2073;
        let v6984: f64 = v2766 - v6752;
        let v6985: f64 = v0 * v6984;
        let v6986: f64 = v6985 * v823;
        let v6987: f64 = v6983 + v6986;
        let v6988: f64 = v0 * v4756;
        let v6989: f64 = v6988 * v1496;
        let v6990: f64 = v6987 + v6989;
        let v6991: f64 = v0 * v5004;
        let v6992: f64 = v6991 * v1748;
        let v6993: f64 = v6990 + v6992;
        let v6994: f64 = v0 * v5193;
        let v6995: f64 = v6994 * v1937;
        let v6996: f64 = v6993 + v6995;
        let v6997: f64 = v0 * v5329;
        let v6998: f64 = v6997 * v2069;
        let v6999: f64 = v6996 + v6998;
        let v7000: f64 = v1492 - v4487;
        let v7001: f64 = v0 * v7000;
        let v7002: f64 = v7001 * v2073;
        let v7003: f64 = v3350 - v6762;
        let v7004: f64 = v0 * v7003;
        let v7005: f64 = v7004 * v823;
        let v7006: f64 = v7002 + v7005;
        let v7007: f64 = v6988 * v1179;
        let v7008: f64 = v7006 + v7007;
        let v7009: f64 = v5361 + v5361;
        let v7010: f64 = v0 * v7009;
        let v7011: f64 = v7010 * v1496;
        let v7012: f64 = v7008 + v7011;
        let v7013: f64 = v5589 + v5610;
        let v7014: f64 = v0 * v7013;
        let v7015: f64 = v7014 * v1748;
        let v7016: f64 = v7012 + v7015;
        let v7017: f64 = v5793 + v5814;
        let v7018: f64 = v0 * v7017;
        let v7019: f64 = v7018 * v1937;
        let v7020: f64 = v7016 + v7019;
        let v7021: f64 = v5967 + v5839;
        let v7022: f64 = v0 * v7021;
        let v7023: f64 = v7022 * v2069;
        let v7024: f64 = v7020 + v7023;
        let v7025: f64 = v1744 - v4766;
        let v7026: f64 = v0 * v7025;
        let v7027: f64 = v7026 * v2073;
        let v7028: f64 = v3835 - v6772;
        let v7029: f64 = v0 * v7028;
        let v7030: f64 = v7029 * v823;
        let v7031: f64 = v7027 + v7030;
        let v7032: f64 = v6991 * v1179;
        let v7033: f64 = v7031 + v7032;
        let v7034: f64 = v5610 + v5589;
        let v7035: f64 = v0 * v7034;
        let v7036: f64 = v7035 * v1496;
        let v7037: f64 = v7033 + v7036;
        let v7038: f64 = v6017 + v6017;
        let v7039: f64 = v0 * v7038;
        let v7040: f64 = v7039 * v1748;
        let v7041: f64 = v7037 + v7040;
        let v7042: f64 = v6203 + v6056;
        let v7043: f64 = v0 * v7042;
        let v7044: f64 = v7043 * v1937;
        let v7045: f64 = v7041 + v7044;
        let v7046: f64 = v6327 + v6362;
        let v7047: f64 = v0 * v7046;
        let v7048: f64 = v7047 * v2069;
        let v7049: f64 = v7045 + v7048;
        let v7050: f64 = v1933 - v5014;
        let v7051: f64 = v0 * v7050;
        let v7052: f64 = v7051 * v2073;
        let v7053: f64 = v4164 - v6782;
        let v7054: f64 = v0 * v7053;
        let v7055: f64 = v7054 * v823;
        let v7056: f64 = v7052 + v7055;
        let v7057: f64 = v6994 * v1179;
        let v7058: f64 = v7056 + v7057;
        let v7059: f64 = v5814 + v5793;
        let v7060: f64 = v0 * v7059;
        let v7061: f64 = v7060 * v1496;
        let v7062: f64 = v7058 + v7061;
        let v7063: f64 = v6056 + v6203;
        let v7064: f64 = v0 * v7063;
        let v7065: f64 = v7064 * v1748;
        let v7066: f64 = v7062 + v7065;
        let v7067: f64 = v6430 + v6430;
        let v7068: f64 = v0 * v7067;
        let v7069: f64 = v7068 * v1937;
        let v7070: f64 = v7066 + v7069;
        let v7071: f64 = v6530 + v6577;
        let v7072: f64 = v0 * v7071;
        let v7073: f64 = v7072 * v2069;
        let v7074: f64 = v7070 + v7073;
        let v7075: f64 = v2065 - v5203;
        let v7076: f64 = v0 * v7075;
        let v7077: f64 = v7076 * v2073;
        let v7078: f64 = v4395 - v6792;
        let v7079: f64 = v0 * v7078;
        let v7080: f64 = v7079 * v823;
        let v7081: f64 = v7077 + v7080;
        let v7082: f64 = v6997 * v1179;
        let v7083: f64 = v7081 + v7082;
        let v7084: f64 = v5839 + v5967;
        let v7085: f64 = v0 * v7084;
        let v7086: f64 = v7085 * v1496;
        let v7087: f64 = v7083 + v7086;
        let v7088: f64 = v6362 + v6327;
        let v7089: f64 = v0 * v7088;
        let v7090: f64 = v7089 * v1748;
        let v7091: f64 = v7087 + v7090;
        let v7092: f64 = v6577 + v6530;
        let v7093: f64 = v0 * v7092;
        let v7094: f64 = v7093 * v1937;
        let v7095: f64 = v7091 + v7094;
        let v7096: f64 = v6655 + v6655;
        let v7097: f64 = v0 * v7096;
        let v7098: f64 = v7097 * v2069;
        let v7099: f64 = v7095 + v7098;
        let v7100: f64 = v739 - v6675;
        let v7101: f64 = v0 * v7100;
        let v7102: f64 = v7101 * v823;
        let v7103: f64 = v5337 + v7102;
        let v7104: f64 = v1128 - v1492;
        let v7105: f64 = v0 * v7104;
        let v7106: f64 = v7105 * v1179;
        let v7107: f64 = v7103 + v7106;
        let v7108: f64 = v1730 - v1413;
        let v7109: f64 = v0 * v7108;
        let v7110: f64 = v7109 * v1748;
        let v7111: f64 = v7107 + v7110;
        let v7112: f64 = v1919 - v1361;
        let v7113: f64 = v0 * v7112;
        let v7114: f64 = v7113 * v1937;
        let v7115: f64 = v7111 + v7114;
        let v7116: f64 = v2051 - v1298;
        let v7117: f64 = v0 * v7116;
        let v7118: f64 = v7117 * v2069;
        let v7119: f64 = v7115 + v7118;
        let v7120: f64 = v739 + v3352;
        let v7121: f64 = v0 * v7120;
        let v7122: f64 = v7121 * v2073;
        let v7123: f64 = v7122 - v6800;
        let v7124: f64 = v2722 - v3350;
        let v7125: f64 = v0 * v7124;
        let v7126: f64 = v7125 * v1179;
        let v7127: f64 = v7123 + v7126;
        (
            v6936,
            v6940,
            v6960,
            v6980,
            v6999,
            v7007,
            v7024,
            v7032,
            v7049,
            v7057,
            v7074,
            v7082,
            v7099,
            v7119,
            v7127,
        )
    };
    let (
        v7139,
        v7159,
        v7179,
        v7204,
        v7216,
        v7227,
        v7239,
        v7248,
        v7268,
        v7288,
        v7308,
        v7324,
        v7325,
    ) = {
        let v7128: f64 = v3821 - v3266;
        let v7129: f64 = v0 * v7128;
        let v7130: f64 = v7129 * v1748;
        let v7131: f64 = v7127 + v7130;
        let v7132: f64 = v4150 - v3219;
        let v7133: f64 = v0 * v7132;
        let v7134: f64 = v7133 * v1937;
        let v7135: f64 = v7131 + v7134;
        let v7136: f64 = v4381 - v3156;
        let v7137: f64 = v0 * v7136;
        let v7138: f64 = v7137 * v2069;
        let v7139: f64 = v7135 + v7138;
        let v7140: f64 = v1128 + v4758;
        let v7141: f64 = v0 * v7140;
        let v7142: f64 = v7141 * v2073;
        let v7143: f64 = v2722 - v6759;
        let v7144: f64 = v0 * v7143;
        let v7145: f64 = v7144 * v823;
        let v7146: f64 = v7142 + v7145;
        let v7147: f64 = v7146 - v7007;
        let v7148: f64 = v4990 - v4689;
        let v7149: f64 = v0 * v7148;
        let v7150: f64 = v7149 * v1748;
        let v7151: f64 = v7147 + v7150;
        let v7152: f64 = v5179 - v4640;
        let v7153: f64 = v0 * v7152;
        let v7154: f64 = v7153 * v1937;
        let v7155: f64 = v7151 + v7154;
        let v7156: f64 = v5315 - v4579;
        let v7157: f64 = v0 * v7156;
        let v7158: f64 = v7157 * v2069;
        let v7159: f64 = v7155 + v7158;
        let v7160: f64 = v1470 + v5363;
        let v7161: f64 = v0 * v7160;
        let v7162: f64 = v7161 * v2073;
        let v7163: f64 = v3328 + v6808;
        let v7164: f64 = v0 * v7163;
        let v7165: f64 = v7164 * v823;
        let v7166: f64 = v7162 + v7165;
        let v7167: f64 = v4734 - v5361;
        let v7168: f64 = v0 * v7167;
        let v7169: f64 = v7168 * v1179;
        let v7170: f64 = v7166 + v7169;
        let v7171: f64 = v0 * v5575;
        let v7172: f64 = v7171 * v1748;
        let v7173: f64 = v7170 + v7172;
        let v7174: f64 = v0 * v5779;
        let v7175: f64 = v7174 * v1937;
        let v7176: f64 = v7173 + v7175;
        let v7177: f64 = v0 * v5953;
        let v7178: f64 = v7177 * v2069;
        let v7179: f64 = v7176 + v7178;
        let v7180: f64 = v1730 + v5612;
        let v7181: f64 = v0 * v7180;
        let v7182: f64 = v7181 * v2073;
        let v7183: f64 = v3821 + v6818;
        let v7184: f64 = v0 * v7183;
        let v7185: f64 = v7184 * v823;
        let v7186: f64 = v7182 + v7185;
        let v7187: f64 = v4990 - v5610;
        let v7188: f64 = v0 * v7187;
        let v7189: f64 = v7188 * v1179;
        let v7190: f64 = v7186 + v7189;
        let v7191: f64 = v7171 * v1496;
        let v7192: f64 = v7190 + v7191;
        let v7193: f64 = v6000 + v6000;
        let v7194: f64 = v0 * v7193;
        let v7195: f64 = v7194 * v1748;
        let v7196: f64 = v7192 - v7195;
        let v7197: f64 = v6189 - v6046;
        let v7198: f64 = v0 * v7197;
        let v7199: f64 = v7198 * v1937;
        let v7200: f64 = v7196 + v7199;
        let v7201: f64 = v6313 - v6345;
        let v7202: f64 = v0 * v7201;
        let v7203: f64 = v7202 * v2069;
        let v7204: f64 = v7200 + v7203;
        let v7205: f64 = v1919 + v5816;
        let v7206: f64 = v0 * v7205;
        let v7207: f64 = v7206 * v2073;
        let v7208: f64 = v4150 + v6828;
        let v7209: f64 = v0 * v7208;
        let v7210: f64 = v7209 * v823;
        let v7211: f64 = v7207 + v7210;
        let v7212: f64 = v5179 - v5814;
        let v7213: f64 = v0 * v7212;
        let v7214: f64 = v7213 * v1179;
        let v7215: f64 = v7211 + v7214;
        let v7216: f64 = v7174 * v1496;
        let v7217: f64 = v7215 + v7216;
        let v7218: f64 = v7198 * v1748;
        let v7219: f64 = v7217 + v7218;
        let v7220: f64 = v6416 + v6416;
        let v7221: f64 = v0 * v7220;
        let v7222: f64 = v7221 * v1937;
        let v7223: f64 = v7219 + v7222;
        let v7224: f64 = v6516 - v6558;
        let v7225: f64 = v0 * v7224;
        let v7226: f64 = v7225 * v2069;
        let v7227: f64 = v7223 + v7226;
        let v7228: f64 = v2051 - v5841;
        let v7229: f64 = v0 * v7228;
        let v7230: f64 = v7229 * v2073;
        let v7231: f64 = v4381 - v6838;
        let v7232: f64 = v0 * v7231;
        let v7233: f64 = v7232 * v823;
        let v7234: f64 = v7230 + v7233;
        let v7235: f64 = v5315 - v5839;
        let v7236: f64 = v0 * v7235;
        let v7237: f64 = v7236 * v1179;
        let v7238: f64 = v7234 + v7237;
        let v7239: f64 = v7177 * v1496;
        let v7240: f64 = v7238 + v7239;
        let v7241: f64 = v7202 * v1748;
        let v7242: f64 = v7240 + v7241;
        let v7243: f64 = v7225 * v1937;
        let v7244: f64 = v7242 + v7243;
        let v7245: f64 = v6634 + v6634;
        let v7246: f64 = v0 * v7245;
        let v7247: f64 = v7246 * v2069;
        let v7248: f64 = v7244 - v7247;
        let v7249: f64 = v684 - v6682;
        let v7250: f64 = v0 * v7249;
        let v7251: f64 = v7250 * v823;
        let v7252: f64 = v5975 + v7251;
        let v7253: f64 = v1074 - v1744;
        let v7254: f64 = v0 * v7253;
        let v7255: f64 = v7254 * v1179;
        let v7256: f64 = v7252 + v7255;
        let v7257: f64 = v1413 - v1730;
        let v7258: f64 = v0 * v7257;
        let v7259: f64 = v7258 * v1496;
        let v7260: f64 = v7256 + v7259;
        let v7261: f64 = v1890 - v1649;
        let v7262: f64 = v0 * v7261;
        let v7263: f64 = v7262 * v1937;
        let v7264: f64 = v7260 + v7263;
        let v7265: f64 = v2026 - v1589;
        let v7266: f64 = v0 * v7265;
        let v7267: f64 = v7266 * v2069;
        let v7268: f64 = v7264 + v7267;
        let v7269: f64 = v684 + v3837;
        let v7270: f64 = v0 * v7269;
        let v7271: f64 = v7270 * v2073;
        let v7272: f64 = v7271 - v6846;
        let v7273: f64 = v2673 - v3835;
        let v7274: f64 = v0 * v7273;
        let v7275: f64 = v7274 * v1179;
        let v7276: f64 = v7272 + v7275;
        let v7277: f64 = v3266 - v3821;
        let v7278: f64 = v0 * v7277;
        let v7279: f64 = v7278 * v1496;
        let v7280: f64 = v7276 + v7279;
        let v7281: f64 = v4121 - v3740;
        let v7282: f64 = v0 * v7281;
        let v7283: f64 = v7282 * v1937;
        let v7284: f64 = v7280 + v7283;
        let v7285: f64 = v4356 - v3680;
        let v7286: f64 = v0 * v7285;
        let v7287: f64 = v7286 * v2069;
        let v7288: f64 = v7284 + v7287;
        let v7289: f64 = v1074 + v5006;
        let v7290: f64 = v0 * v7289;
        let v7291: f64 = v7290 * v2073;
        let v7292: f64 = v2673 - v6769;
        let v7293: f64 = v0 * v7292;
        let v7294: f64 = v7293 * v823;
        let v7295: f64 = v7291 + v7294;
        let v7296: f64 = v7295 - v7032;
        let v7297: f64 = v4689 - v4990;
        let v7298: f64 = v0 * v7297;
        let v7299: f64 = v7298 * v1496;
        let v7300: f64 = v7296 + v7299;
        let v7301: f64 = v5150 - v4932;
        let v7302: f64 = v0 * v7301;
        let v7303: f64 = v7302 * v1937;
        let v7304: f64 = v7300 + v7303;
        let v7305: f64 = v5290 - v4844;
        let v7306: f64 = v0 * v7305;
        let v7307: f64 = v7306 * v2069;
        let v7308: f64 = v7304 + v7307;
        let v7309: f64 = v1413 + v5591;
        let v7310: f64 = v0 * v7309;
        let v7311: f64 = v7310 * v2073;
        let v7312: f64 = v3266 - v6815;
        let v7313: f64 = v0 * v7312;
        let v7314: f64 = v7313 * v823;
        let v7315: f64 = v7311 + v7314;
        let v7316: f64 = v4689 - v5589;
        let v7317: f64 = v0 * v7316;
        let v7318: f64 = v7317 * v1179;
        let v7319: f64 = v7315 + v7318;
        let v7320: f64 = v7319 - v7191;
        let v7321: f64 = v5750 - v5517;
        let v7322: f64 = v0 * v7321;
        let v7323: f64 = v7322 * v1937;
        let v7324: f64 = v7320 + v7323;
        let v7325: f64 = v5928 - v5437;
        (
            v7139,
            v7159,
            v7179,
            v7204,
            v7216,
            v7227,
            v7239,
            v7248,
            v7268,
            v7288,
            v7308,
            v7324,
            v7325,
        )
    };
    let (
        v7328,
        v7349,
        v7374,
        v7390,
        v7399,
        v7419,
        v7439,
        v7459,
        v7479,
        v7499,
        v7519,
        v7521,
        v7523,
    ) = {
        let v7326: f64 = v0 * v7325;
        let v7327: f64 = v7326 * v2069;
        let v7328: f64 = v7324 + v7327;
        let v7329: f64 = v1689 - v6019;
        let v7330: f64 = v0 * v7329;
        let v7331: f64 = v7330 * v2073;
        let v7332: f64 = v3780 - v6856;
        let v7333: f64 = v0 * v7332;
        let v7334: f64 = v7333 * v823;
        let v7335: f64 = v7331 + v7334;
        let v7336: f64 = v4949 - v6017;
        let v7337: f64 = v0 * v7336;
        let v7338: f64 = v7337 * v1179;
        let v7339: f64 = v7335 + v7338;
        let v7340: f64 = v5534 + v6000;
        let v7341: f64 = v0 * v7340;
        let v7342: f64 = v7341 * v1496;
        let v7343: f64 = v7339 + v7342;
        let v7344: f64 = v0 * v6160;
        let v7345: f64 = v7344 * v1937;
        let v7346: f64 = v7343 + v7345;
        let v7347: f64 = v0 * v6292;
        let v7348: f64 = v7347 * v2069;
        let v7349: f64 = v7346 - v7348;
        let v7350: f64 = v1890 - v6058;
        let v7351: f64 = v0 * v7350;
        let v7352: f64 = v7351 * v2073;
        let v7353: f64 = v4121 - v6866;
        let v7354: f64 = v0 * v7353;
        let v7355: f64 = v7354 * v823;
        let v7356: f64 = v7352 + v7355;
        let v7357: f64 = v5150 - v6056;
        let v7358: f64 = v0 * v7357;
        let v7359: f64 = v7358 * v1179;
        let v7360: f64 = v7356 + v7359;
        let v7361: f64 = v5750 + v6046;
        let v7362: f64 = v0 * v7361;
        let v7363: f64 = v7362 * v1496;
        let v7364: f64 = v7360 + v7363;
        let v7365: f64 = v7344 * v1748;
        let v7366: f64 = v7364 + v7365;
        let v7367: f64 = v6395 + v6395;
        let v7368: f64 = v0 * v7367;
        let v7369: f64 = v7368 * v1937;
        let v7370: f64 = v7366 + v7369;
        let v7371: f64 = v6491 + v6544;
        let v7372: f64 = v0 * v7371;
        let v7373: f64 = v7372 * v2069;
        let v7374: f64 = v7370 + v7373;
        let v7375: f64 = v2026 + v6364;
        let v7376: f64 = v0 * v7375;
        let v7377: f64 = v7376 * v2073;
        let v7378: f64 = v4356 - v6876;
        let v7379: f64 = v0 * v7378;
        let v7380: f64 = v7379 * v823;
        let v7381: f64 = v7377 + v7380;
        let v7382: f64 = v5290 - v6362;
        let v7383: f64 = v0 * v7382;
        let v7384: f64 = v7383 * v1179;
        let v7385: f64 = v7381 + v7384;
        let v7386: f64 = v5928 + v6345;
        let v7387: f64 = v0 * v7386;
        let v7388: f64 = v7387 * v1496;
        let v7389: f64 = v7385 + v7388;
        let v7390: f64 = v7347 * v1748;
        let v7391: f64 = v7389 - v7390;
        let v7392: f64 = v6544 + v6491;
        let v7393: f64 = v0 * v7392;
        let v7394: f64 = v7393 * v1937;
        let v7395: f64 = v7391 + v7394;
        let v7396: f64 = v6618 + v6618;
        let v7397: f64 = v0 * v7396;
        let v7398: f64 = v7397 * v2069;
        let v7399: f64 = v7395 + v7398;
        let v7400: f64 = v631 - v6689;
        let v7401: f64 = v0 * v7400;
        let v7402: f64 = v7401 * v823;
        let v7403: f64 = v6370 + v7402;
        let v7404: f64 = v1021 - v1933;
        let v7405: f64 = v0 * v7404;
        let v7406: f64 = v7405 * v1179;
        let v7407: f64 = v7403 + v7406;
        let v7408: f64 = v1361 - v1919;
        let v7409: f64 = v0 * v7408;
        let v7410: f64 = v7409 * v1496;
        let v7411: f64 = v7407 + v7410;
        let v7412: f64 = v1649 - v1890;
        let v7413: f64 = v0 * v7412;
        let v7414: f64 = v7413 * v1748;
        let v7415: f64 = v7411 + v7414;
        let v7416: f64 = v2019 - v1816;
        let v7417: f64 = v0 * v7416;
        let v7418: f64 = v7417 * v2069;
        let v7419: f64 = v7415 + v7418;
        let v7420: f64 = v631 + v4166;
        let v7421: f64 = v0 * v7420;
        let v7422: f64 = v7421 * v2073;
        let v7423: f64 = v7422 - v6884;
        let v7424: f64 = v2620 - v4164;
        let v7425: f64 = v0 * v7424;
        let v7426: f64 = v7425 * v1179;
        let v7427: f64 = v7423 + v7426;
        let v7428: f64 = v3219 - v4150;
        let v7429: f64 = v0 * v7428;
        let v7430: f64 = v7429 * v1496;
        let v7431: f64 = v7427 + v7430;
        let v7432: f64 = v3740 - v4121;
        let v7433: f64 = v0 * v7432;
        let v7434: f64 = v7433 * v1748;
        let v7435: f64 = v7431 + v7434;
        let v7436: f64 = v4349 - v4047;
        let v7437: f64 = v0 * v7436;
        let v7438: f64 = v7437 * v2069;
        let v7439: f64 = v7435 + v7438;
        let v7440: f64 = v1021 + v5195;
        let v7441: f64 = v0 * v7440;
        let v7442: f64 = v7441 * v2073;
        let v7443: f64 = v2620 - v6779;
        let v7444: f64 = v0 * v7443;
        let v7445: f64 = v7444 * v823;
        let v7446: f64 = v7442 + v7445;
        let v7447: f64 = v7446 - v7057;
        let v7448: f64 = v4640 - v5179;
        let v7449: f64 = v0 * v7448;
        let v7450: f64 = v7449 * v1496;
        let v7451: f64 = v7447 + v7450;
        let v7452: f64 = v4932 - v5150;
        let v7453: f64 = v0 * v7452;
        let v7454: f64 = v7453 * v1748;
        let v7455: f64 = v7451 + v7454;
        let v7456: f64 = v5283 - v5076;
        let v7457: f64 = v0 * v7456;
        let v7458: f64 = v7457 * v2069;
        let v7459: f64 = v7455 + v7458;
        let v7460: f64 = v1361 + v5795;
        let v7461: f64 = v0 * v7460;
        let v7462: f64 = v7461 * v2073;
        let v7463: f64 = v3219 - v6825;
        let v7464: f64 = v0 * v7463;
        let v7465: f64 = v7464 * v823;
        let v7466: f64 = v7462 + v7465;
        let v7467: f64 = v4640 - v5793;
        let v7468: f64 = v0 * v7467;
        let v7469: f64 = v7468 * v1179;
        let v7470: f64 = v7466 + v7469;
        let v7471: f64 = v7470 - v7216;
        let v7472: f64 = v5517 - v5750;
        let v7473: f64 = v0 * v7472;
        let v7474: f64 = v7473 * v1748;
        let v7475: f64 = v7471 + v7474;
        let v7476: f64 = v5921 - v5676;
        let v7477: f64 = v0 * v7476;
        let v7478: f64 = v7477 * v2069;
        let v7479: f64 = v7475 + v7478;
        let v7480: f64 = v1649 + v6205;
        let v7481: f64 = v0 * v7480;
        let v7482: f64 = v7481 * v2073;
        let v7483: f64 = v3740 - v6863;
        let v7484: f64 = v0 * v7483;
        let v7485: f64 = v7484 * v823;
        let v7486: f64 = v7482 + v7485;
        let v7487: f64 = v4932 - v6203;
        let v7488: f64 = v0 * v7487;
        let v7489: f64 = v7488 * v1179;
        let v7490: f64 = v7486 + v7489;
        let v7491: f64 = v5517 - v6189;
        let v7492: f64 = v0 * v7491;
        let v7493: f64 = v7492 * v1496;
        let v7494: f64 = v7490 + v7493;
        let v7495: f64 = v7494 - v7365;
        let v7496: f64 = v6281 - v6098;
        let v7497: f64 = v0 * v7496;
        let v7498: f64 = v7497 * v2069;
        let v7499: f64 = v7495 + v7498;
        let v7500: f64 = v1879 + v6432;
        let v7501: f64 = v0 * v7500;
        let v7502: f64 = v7501 * v2073;
        let v7503: f64 = v4110 - v6898;
        let v7504: f64 = v0 * v7503;
        let v7505: f64 = v7504 * v823;
        let v7506: f64 = v7502 + v7505;
        let v7507: f64 = v5139 - v6430;
        let v7508: f64 = v0 * v7507;
        let v7509: f64 = v7508 * v1179;
        let v7510: f64 = v7506 + v7509;
        let v7511: f64 = v5739 - v6416;
        let v7512: f64 = v0 * v7511;
        let v7513: f64 = v7512 * v1496;
        let v7514: f64 = v7510 + v7513;
        let v7515: f64 = v6149 - v6395;
        let v7516: f64 = v0 * v7515;
        let v7517: f64 = v7516 * v1748;
        let v7518: f64 = v7514 + v7517;
        let v7519: f64 = v0 * v6484;
        let v7520: f64 = v7519 * v2069;
        let v7521: f64 = v7518 + v7520;
        let v7522: f64 = v2019 + v6579;
        let v7523: f64 = v0 * v7522;
        (
            v7328,
            v7349,
            v7374,
            v7390,
            v7399,
            v7419,
            v7439,
            v7459,
            v7479,
            v7499,
            v7519,
            v7521,
            v7523,
        )
    };
    let (v7546, v7566, v7586, v7606, v7626, v7646, v7666, v7685) = {
        let v7524: f64 = v7523 * v2073;
        let v7525: f64 = v4349 - v6908;
        let v7526: f64 = v0 * v7525;
        let v7527: f64 = v7526 * v823;
        let v7528: f64 = v7524 + v7527;
        let v7529: f64 = v5283 - v6577;
        let v7530: f64 = v0 * v7529;
        let v7531: f64 = v7530 * v1179;
        let v7532: f64 = v7528 + v7531;
        let v7533: f64 = v5921 + v6558;
        let v7534: f64 = v0 * v7533;
        let v7535: f64 = v7534 * v1496;
        let v7536: f64 = v7532 + v7535;
        let v7537: f64 = v6281 - v6544;
        let v7538: f64 = v0 * v7537;
        let v7539: f64 = v7538 * v1748;
        let v7540: f64 = v7536 + v7539;
        let v7541: f64 = v7519 * v1937;
        let v7542: f64 = v7540 + v7541;
        let v7543: f64 = v6451 + v6451;
        let v7544: f64 = v0 * v7543;
        let v7545: f64 = v7544 * v2069;
        let v7546: f64 = v7542 + v7545;
        let v7547: f64 = v568 - v6696;
        let v7548: f64 = v0 * v7547;
        let v7549: f64 = v7548 * v823;
        let v7550: f64 = v6585 + v7549;
        let v7551: f64 = v958 - v2065;
        let v7552: f64 = v0 * v7551;
        let v7553: f64 = v7552 * v1179;
        let v7554: f64 = v7550 + v7553;
        let v7555: f64 = v1298 - v2051;
        let v7556: f64 = v0 * v7555;
        let v7557: f64 = v7556 * v1496;
        let v7558: f64 = v7554 + v7557;
        let v7559: f64 = v1589 - v2026;
        let v7560: f64 = v0 * v7559;
        let v7561: f64 = v7560 * v1748;
        let v7562: f64 = v7558 + v7561;
        let v7563: f64 = v1816 - v2019;
        let v7564: f64 = v0 * v7563;
        let v7565: f64 = v7564 * v1937;
        let v7566: f64 = v7562 + v7565;
        let v7567: f64 = v568 + v4397;
        let v7568: f64 = v0 * v7567;
        let v7569: f64 = v7568 * v2073;
        let v7570: f64 = v7569 - v6916;
        let v7571: f64 = v2557 - v4395;
        let v7572: f64 = v0 * v7571;
        let v7573: f64 = v7572 * v1179;
        let v7574: f64 = v7570 + v7573;
        let v7575: f64 = v3156 - v4381;
        let v7576: f64 = v0 * v7575;
        let v7577: f64 = v7576 * v1496;
        let v7578: f64 = v7574 + v7577;
        let v7579: f64 = v3680 - v4356;
        let v7580: f64 = v0 * v7579;
        let v7581: f64 = v7580 * v1748;
        let v7582: f64 = v7578 + v7581;
        let v7583: f64 = v4047 - v4349;
        let v7584: f64 = v0 * v7583;
        let v7585: f64 = v7584 * v1937;
        let v7586: f64 = v7582 + v7585;
        let v7587: f64 = v958 + v5331;
        let v7588: f64 = v0 * v7587;
        let v7589: f64 = v7588 * v2073;
        let v7590: f64 = v2557 - v6789;
        let v7591: f64 = v0 * v7590;
        let v7592: f64 = v7591 * v823;
        let v7593: f64 = v7589 + v7592;
        let v7594: f64 = v7593 - v7082;
        let v7595: f64 = v4579 - v5315;
        let v7596: f64 = v0 * v7595;
        let v7597: f64 = v7596 * v1496;
        let v7598: f64 = v7594 + v7597;
        let v7599: f64 = v4844 - v5290;
        let v7600: f64 = v0 * v7599;
        let v7601: f64 = v7600 * v1748;
        let v7602: f64 = v7598 + v7601;
        let v7603: f64 = v5076 - v5283;
        let v7604: f64 = v0 * v7603;
        let v7605: f64 = v7604 * v1937;
        let v7606: f64 = v7602 + v7605;
        let v7607: f64 = v1298 + v5969;
        let v7608: f64 = v0 * v7607;
        let v7609: f64 = v7608 * v2073;
        let v7610: f64 = v3156 - v6835;
        let v7611: f64 = v0 * v7610;
        let v7612: f64 = v7611 * v823;
        let v7613: f64 = v7609 + v7612;
        let v7614: f64 = v4579 - v5967;
        let v7615: f64 = v0 * v7614;
        let v7616: f64 = v7615 * v1179;
        let v7617: f64 = v7613 + v7616;
        let v7618: f64 = v7617 - v7239;
        let v7619: f64 = v5437 - v5928;
        let v7620: f64 = v0 * v7619;
        let v7621: f64 = v7620 * v1748;
        let v7622: f64 = v7618 + v7621;
        let v7623: f64 = v5676 - v5921;
        let v7624: f64 = v0 * v7623;
        let v7625: f64 = v7624 * v1937;
        let v7626: f64 = v7622 + v7625;
        let v7627: f64 = v1589 + v6329;
        let v7628: f64 = v0 * v7627;
        let v7629: f64 = v7628 * v2073;
        let v7630: f64 = v3680 - v6873;
        let v7631: f64 = v0 * v7630;
        let v7632: f64 = v7631 * v823;
        let v7633: f64 = v7629 + v7632;
        let v7634: f64 = v4844 - v6327;
        let v7635: f64 = v0 * v7634;
        let v7636: f64 = v7635 * v1179;
        let v7637: f64 = v7633 + v7636;
        let v7638: f64 = v5437 - v6313;
        let v7639: f64 = v0 * v7638;
        let v7640: f64 = v7639 * v1496;
        let v7641: f64 = v7637 + v7640;
        let v7642: f64 = v7641 + v7390;
        let v7643: f64 = v6098 - v6281;
        let v7644: f64 = v0 * v7643;
        let v7645: f64 = v7644 * v1937;
        let v7646: f64 = v7642 + v7645;
        let v7647: f64 = v1816 + v6532;
        let v7648: f64 = v0 * v7647;
        let v7649: f64 = v7648 * v2073;
        let v7650: f64 = v4047 - v6905;
        let v7651: f64 = v0 * v7650;
        let v7652: f64 = v7651 * v823;
        let v7653: f64 = v7649 + v7652;
        let v7654: f64 = v5076 - v6530;
        let v7655: f64 = v0 * v7654;
        let v7656: f64 = v7655 * v1179;
        let v7657: f64 = v7653 + v7656;
        let v7658: f64 = v5676 - v6516;
        let v7659: f64 = v0 * v7658;
        let v7660: f64 = v7659 * v1496;
        let v7661: f64 = v7657 + v7660;
        let v7662: f64 = v6098 - v6491;
        let v7663: f64 = v0 * v7662;
        let v7664: f64 = v7663 * v1748;
        let v7665: f64 = v7661 + v7664;
        let v7666: f64 = v7665 - v7541;
        let v7667: f64 = v1976 + v6657;
        let v7668: f64 = v0 * v7667;
        let v7669: f64 = v7668 * v2073;
        let v7670: f64 = v4306 - v6936;
        let v7671: f64 = v0 * v7670;
        let v7672: f64 = v7671 * v823;
        let v7673: f64 = v7669 + v7672;
        let v7674: f64 = v5240 - v6655;
        let v7675: f64 = v0 * v7674;
        let v7676: f64 = v7675 * v1179;
        let v7677: f64 = v7673 + v7676;
        let v7678: f64 = v5878 + v6634;
        let v7679: f64 = v0 * v7678;
        let v7680: f64 = v7679 * v1496;
        let v7681: f64 = v7677 + v7680;
        let v7682: f64 = v6220 - v6618;
        let v7683: f64 = v0 * v7682;
        let v7684: f64 = v7683 * v1748;
        let v7685: f64 = v7681 + v7684;
        (v7546, v7566, v7586, v7606, v7626, v7646, v7666, v7685)
    };
    [
        [v2072, v4470, v5335, v5973, v6368, v6583, v6661],
        [v6700, v6744, v6796, v6842, v6880, v6912, v6940],
        [v6960, v6980, v6999, v7024, v7049, v7074, v7099],
        [v7119, v7139, v7159, v7179, v7204, v7227, v7248],
        [v7268, v7288, v7308, v7328, v7349, v7374, v7399],
        [v7419, v7439, v7459, v7479, v7499, v7521, v7546],
        [v7566, v7586, v7606, v7626, v7646, v7666, v7685],
    ]
}
/// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
///
/// # Inputs
///
/// - `q: &[f64; 7]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 7]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 70]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis: [f64; 7]`: c(q, qd) = C(q, qd) qd (N m or N)
///
/// Operation count: 757 floating-point operations, 12 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis(q: &[f64; 7], qd: &[f64; 7], params: &[f64; 70]) -> [f64; 7] {
    let (
        v1,
        v2,
        v4,
        v5,
        v6,
        v8,
        v9,
        v10,
        v11,
        v16,
        v18,
        v21,
        v25,
        v28,
        v31,
        v33,
        v34,
        v35,
        v38,
        v42,
        v44,
        v48,
        v50,
        v53,
        v57,
        v60,
        v61,
        v63,
        v66,
        v70,
        v74,
        v75,
        v80,
        v82,
        v85,
        v88,
        v90,
        v91,
        v93,
        v98,
        v101,
        v103,
        v109,
        v111,
        v114,
        v118,
        v121,
        v122,
        v124,
        v127,
        v131,
        v135,
        v136,
        v141,
        v143,
        v148,
        v152,
        v156,
        v158,
        v161,
        v163,
        v164,
        v166,
        v168,
    ) = {
        let v0: f64 = q[1];
        let (v1, v9): (f64, f64) = ::armdyn_runtime::libm::sincos(v0);
        let v2: f64 = params[15];
        let v3: f64 = qd[0];
        let v4: f64 = v1 * v3;
        let v5: f64 = qd[1];
        let v6: f64 = v4 * v5;
        let v7: f64 = v2 * v6;
        let v8: f64 = params[14];
        let v10: f64 = v9 * v3;
        let v11: f64 = v10 * v5;
        let v12: f64 = v8 * v11;
        let v13: f64 = v7 - v12;
        let v14: f64 = params[19];
        let v15: f64 = v14 * v5;
        let v16: f64 = params[16];
        let v17: f64 = v16 * v4;
        let v18: f64 = params[18];
        let v19: f64 = v18 * v10;
        let v20: f64 = v17 + v19;
        let v21: f64 = v15 - v20;
        let v22: f64 = v10 * v21;
        let v23: f64 = v18 * v5;
        let v24: f64 = v2 * v4;
        let v25: f64 = params[17];
        let v26: f64 = v25 * v10;
        let v27: f64 = v24 + v26;
        let v28: f64 = v23 - v27;
        let v29: f64 = v5 * v28;
        let v30: f64 = v22 + v29;
        let v31: f64 = v13 - v30;
        let v32: f64 = q[2];
        let (v35, v33): (f64, f64) = ::armdyn_runtime::libm::sincos(v32);
        let v34: f64 = params[24];
        let v36: f64 = v35 * v4;
        let v37: f64 = v33 * v5;
        let v38: f64 = v36 + v37;
        let v39: f64 = qd[2];
        let v40: f64 = v38 * v39;
        let v41: f64 = v33 * v11;
        let v42: f64 = v40 - v41;
        let v43: f64 = v34 * v42;
        let v44: f64 = params[25];
        let v45: f64 = v35 * v11;
        let v46: f64 = v35 * v5;
        let v47: f64 = v33 * v4;
        let v48: f64 = v46 - v47;
        let v49: f64 = v48 * v39;
        let v50: f64 = v45 - v49;
        let v51: f64 = v44 * v50;
        let v52: f64 = v43 + v51;
        let v53: f64 = params[26];
        let v54: f64 = v53 * v6;
        let v55: f64 = v52 - v54;
        let v56: f64 = v53 * v48;
        let v57: f64 = params[28];
        let v58: f64 = v57 * v38;
        let v59: f64 = v56 + v58;
        let v60: f64 = params[29];
        let v61: f64 = v10 + v39;
        let v62: f64 = v60 * v61;
        let v63: f64 = v59 + v62;
        let v64: f64 = v38 * v63;
        let v65: f64 = v44 * v48;
        let v66: f64 = params[27];
        let v67: f64 = v66 * v38;
        let v68: f64 = v65 + v67;
        let v69: f64 = v57 * v61;
        let v70: f64 = v68 + v69;
        let v71: f64 = v61 * v70;
        let v72: f64 = v64 - v71;
        let v73: f64 = v55 + v72;
        let v74: f64 = params[22];
        let v75: f64 = 0.316_f64;
        let v76: f64 = v75 * v48;
        let v77: f64 = v48 * v76;
        let v78: f64 = v75 * v38;
        let v79: f64 = v38 * v78;
        let v80: f64 = v77 + v79;
        let v81: f64 = v74 * v80;
        let v82: f64 = params[23];
        let v83: f64 = v61 * v78;
        let v84: f64 = v75 * v42;
        let v85: f64 = v83 - v84;
        let v86: f64 = v82 * v85;
        let v87: f64 = v81 + v86;
        let v88: f64 = v73 - v87;
        let v89: f64 = q[3];
        let (v93, v90): (f64, f64) = ::armdyn_runtime::libm::sincos(v89);
        let v91: f64 = params[34];
        let v92: f64 = v90 * v42;
        let v94: f64 = v93 * v6;
        let v95: f64 = v92 - v94;
        let v96: f64 = v90 * v61;
        let v97: f64 = v93 * v48;
        let v98: f64 = v96 - v97;
        let v99: f64 = qd[3];
        let v100: f64 = v98 * v99;
        let v101: f64 = v95 + v100;
        let v102: f64 = v91 * v101;
        let v103: f64 = params[35];
        let v104: f64 = v93 * v42;
        let v105: f64 = v90 * v6;
        let v106: f64 = v104 + v105;
        let v107: f64 = v90 * v48;
        let v108: f64 = v93 * v61;
        let v109: f64 = v107 + v108;
        let v110: f64 = v109 * v99;
        let v111: f64 = v106 + v110;
        let v112: f64 = v103 * v111;
        let v113: f64 = v102 - v112;
        let v114: f64 = params[36];
        let v115: f64 = v114 * v50;
        let v116: f64 = v113 - v115;
        let v117: f64 = v114 * v109;
        let v118: f64 = params[38];
        let v119: f64 = v118 * v98;
        let v120: f64 = v117 + v119;
        let v121: f64 = params[39];
        let v122: f64 = v99 - v38;
        let v123: f64 = v121 * v122;
        let v124: f64 = v120 + v123;
        let v125: f64 = v98 * v124;
        let v126: f64 = v103 * v109;
        let v127: f64 = params[37];
        let v128: f64 = v127 * v98;
        let v129: f64 = v126 + v128;
        let v130: f64 = v118 * v122;
        let v131: f64 = v129 + v130;
        let v132: f64 = v122 * v131;
        let v133: f64 = v125 - v132;
        let v134: f64 = v116 + v133;
        let v135: f64 = params[32];
        let v136: f64 = 0.0825_f64;
        let v137: f64 = v136 * v38;
        let v138: f64 = v48 * v137;
        let v139: f64 = v136 * v6;
        let v140: f64 = v138 - v139;
        let v141: f64 = v85 + v140;
        let v142: f64 = v135 * v141;
        let v143: f64 = params[33];
        let v144: f64 = v136 * v61;
        let v145: f64 = v48 * v144;
        let v146: f64 = v136 * v50;
        let v147: f64 = v145 - v146;
        let v148: f64 = v147 - v80;
        let v149: f64 = v90 * v148;
        let v150: f64 = v75 * v50;
        let v151: f64 = v61 * v76;
        let v152: f64 = v150 + v151;
        let v153: f64 = v38 * v137;
        let v154: f64 = v61 * v144;
        let v155: f64 = v153 + v154;
        let v156: f64 = v152 - v155;
        let v157: f64 = v93 * v156;
        let v158: f64 = v149 - v157;
        let v159: f64 = v143 * v158;
        let v160: f64 = v142 + v159;
        let v161: f64 = v134 - v160;
        let v162: f64 = q[4];
        let (v166, v163): (f64, f64) = ::armdyn_runtime::libm::sincos(v162);
        let v164: f64 = params[44];
        let v165: f64 = v163 * v101;
        let v167: f64 = v166 * v50;
        let v168: f64 = v165 + v167;
        (
            v1,
            v2,
            v4,
            v5,
            v6,
            v8,
            v9,
            v10,
            v11,
            v16,
            v18,
            v21,
            v25,
            v28,
            v31,
            v33,
            v34,
            v35,
            v38,
            v42,
            v44,
            v48,
            v50,
            v53,
            v57,
            v60,
            v61,
            v63,
            v66,
            v70,
            v74,
            v75,
            v80,
            v82,
            v85,
            v88,
            v90,
            v91,
            v93,
            v98,
            v101,
            v103,
            v109,
            v111,
            v114,
            v118,
            v121,
            v122,
            v124,
            v127,
            v131,
            v135,
            v136,
            v141,
            v143,
            v148,
            v152,
            v156,
            v158,
            v161,
            v163,
            v164,
            v166,
            v168,
        )
    };
    let (
        v171,
        v174,
        v176,
        v182,
        v184,
        v187,
        v191,
        v194,
        v195,
        v197,
        v200,
        v204,
        v208,
        v209,
        v215,
        v221,
        v223,
        v226,
        v242,
        v245,
        v247,
        v248,
        v250,
        v255,
        v258,
        v260,
        v266,
        v268,
        v271,
        v275,
        v278,
        v279,
        v281,
        v284,
        v288,
        v292,
        v294,
        v302,
        v304,
        v307,
        v309,
        v310,
        v312,
        v317,
        v318,
        v320,
        v322,
        v328,
        v330,
        v333,
        v335,
        v336,
        v337,
    ) = {
        let v169: f64 = v166 * v109;
        let v170: f64 = v163 * v122;
        let v171: f64 = v169 + v170;
        let v172: f64 = qd[4];
        let v173: f64 = v171 * v172;
        let v174: f64 = v168 - v173;
        let v175: f64 = v164 * v174;
        let v176: f64 = params[45];
        let v177: f64 = v163 * v50;
        let v178: f64 = v166 * v101;
        let v179: f64 = v177 - v178;
        let v180: f64 = v163 * v109;
        let v181: f64 = v166 * v122;
        let v182: f64 = v180 - v181;
        let v183: f64 = v182 * v172;
        let v184: f64 = v179 - v183;
        let v185: f64 = v176 * v184;
        let v186: f64 = v175 + v185;
        let v187: f64 = params[46];
        let v188: f64 = v187 * v111;
        let v189: f64 = v186 - v188;
        let v190: f64 = v187 * v182;
        let v191: f64 = params[48];
        let v192: f64 = v191 * v171;
        let v193: f64 = v190 - v192;
        let v194: f64 = params[49];
        let v195: f64 = v98 + v172;
        let v196: f64 = v194 * v195;
        let v197: f64 = v193 + v196;
        let v198: f64 = v171 * v197;
        let v199: f64 = v176 * v182;
        let v200: f64 = params[47];
        let v201: f64 = v200 * v171;
        let v202: f64 = v199 - v201;
        let v203: f64 = v191 * v195;
        let v204: f64 = v202 + v203;
        let v205: f64 = v195 * v204;
        let v206: f64 = v198 + v205;
        let v207: f64 = v189 - v206;
        let v208: f64 = params[42];
        let v209: f64 = -0.0825_f64;
        let v210: f64 = v209 * v98;
        let v211: f64 = v109 * v210;
        let v212: f64 = v209 * v50;
        let v213: f64 = v211 - v212;
        let v214: f64 = v158 + v213;
        let v215: f64 = 0.384_f64;
        let v216: f64 = v215 * v182;
        let v217: f64 = v182 * v216;
        let v218: f64 = v215 * v171;
        let v219: f64 = v171 * v218;
        let v220: f64 = v217 + v219;
        let v221: f64 = v214 - v220;
        let v222: f64 = v208 * v221;
        let v223: f64 = params[43];
        let v224: f64 = v90 * v156;
        let v225: f64 = v93 * v148;
        let v226: f64 = v224 + v225;
        let v227: f64 = v98 * v210;
        let v228: f64 = v209 * v122;
        let v229: f64 = v122 * v228;
        let v230: f64 = v227 + v229;
        let v231: f64 = v226 - v230;
        let v232: f64 = v166 * v231;
        let v233: f64 = v209 * v111;
        let v234: f64 = v109 * v228;
        let v235: f64 = v233 + v234;
        let v236: f64 = v235 - v141;
        let v237: f64 = v163 * v236;
        let v238: f64 = v232 + v237;
        let v239: f64 = v215 * v174;
        let v240: f64 = v195 * v218;
        let v241: f64 = v239 + v240;
        let v242: f64 = v238 + v241;
        let v243: f64 = v223 * v242;
        let v244: f64 = v222 + v243;
        let v245: f64 = v207 + v244;
        let v246: f64 = q[5];
        let (v250, v247): (f64, f64) = ::armdyn_runtime::libm::sincos(v246);
        let v248: f64 = params[54];
        let v249: f64 = v247 * v174;
        let v251: f64 = v250 * v111;
        let v252: f64 = v249 - v251;
        let v253: f64 = v247 * v195;
        let v254: f64 = v250 * v182;
        let v255: f64 = v253 - v254;
        let v256: f64 = qd[5];
        let v257: f64 = v255 * v256;
        let v258: f64 = v252 + v257;
        let v259: f64 = v248 * v258;
        let v260: f64 = params[55];
        let v261: f64 = v250 * v174;
        let v262: f64 = v247 * v111;
        let v263: f64 = v261 + v262;
        let v264: f64 = v247 * v182;
        let v265: f64 = v250 * v195;
        let v266: f64 = v264 + v265;
        let v267: f64 = v266 * v256;
        let v268: f64 = v263 + v267;
        let v269: f64 = v260 * v268;
        let v270: f64 = v259 - v269;
        let v271: f64 = params[56];
        let v272: f64 = v271 * v184;
        let v273: f64 = v270 - v272;
        let v274: f64 = v271 * v266;
        let v275: f64 = params[58];
        let v276: f64 = v275 * v255;
        let v277: f64 = v274 + v276;
        let v278: f64 = params[59];
        let v279: f64 = v171 + v256;
        let v280: f64 = v278 * v279;
        let v281: f64 = v277 + v280;
        let v282: f64 = v255 * v281;
        let v283: f64 = v260 * v266;
        let v284: f64 = params[57];
        let v285: f64 = v284 * v255;
        let v286: f64 = v283 + v285;
        let v287: f64 = v275 * v279;
        let v288: f64 = v286 + v287;
        let v289: f64 = v279 * v288;
        let v290: f64 = v282 - v289;
        let v291: f64 = v273 + v290;
        let v292: f64 = params[52];
        let v293: f64 = v292 * v242;
        let v294: f64 = params[53];
        let v295: f64 = v247 * v221;
        let v296: f64 = v163 * v231;
        let v297: f64 = v166 * v236;
        let v298: f64 = v296 - v297;
        let v299: f64 = v215 * v184;
        let v300: f64 = v195 * v216;
        let v301: f64 = v299 + v300;
        let v302: f64 = v298 + v301;
        let v303: f64 = v250 * v302;
        let v304: f64 = v295 - v303;
        let v305: f64 = v294 * v304;
        let v306: f64 = v293 - v305;
        let v307: f64 = v291 + v306;
        let v308: f64 = q[6];
        let (v312, v309): (f64, f64) = ::armdyn_runtime::libm::sincos(v308);
        let v310: f64 = params[64];
        let v311: f64 = v309 * v258;
        let v313: f64 = v312 * v184;
        let v314: f64 = v311 - v313;
        let v315: f64 = v309 * v279;
        let v316: f64 = v312 * v266;
        let v317: f64 = v315 - v316;
        let v318: f64 = qd[6];
        let v319: f64 = v317 * v318;
        let v320: f64 = v314 + v319;
        let v321: f64 = v310 * v320;
        let v322: f64 = params[65];
        let v323: f64 = v312 * v258;
        let v324: f64 = v309 * v184;
        let v325: f64 = v323 + v324;
        let v326: f64 = v309 * v266;
        let v327: f64 = v312 * v279;
        let v328: f64 = v326 + v327;
        let v329: f64 = v328 * v318;
        let v330: f64 = v325 + v329;
        let v331: f64 = v322 * v330;
        let v332: f64 = v321 - v331;
        let v333: f64 = params[66];
        let v334: f64 = v333 * v268;
        let v335: f64 = v332 + v334;
        let v336: f64 = v333 * v328;
        let v337: f64 = params[68];
        (
            v171,
            v174,
            v176,
            v182,
            v184,
            v187,
            v191,
            v194,
            v195,
            v197,
            v200,
            v204,
            v208,
            v209,
            v215,
            v221,
            v223,
            v226,
            v242,
            v245,
            v247,
            v248,
            v250,
            v255,
            v258,
            v260,
            v266,
            v268,
            v271,
            v275,
            v278,
            v279,
            v281,
            v284,
            v288,
            v292,
            v294,
            v302,
            v304,
            v307,
            v309,
            v310,
            v312,
            v317,
            v318,
            v320,
            v322,
            v328,
            v330,
            v333,
            v335,
            v336,
            v337,
        )
    };
    let (
        v354,
        v355,
        v360,
        v371,
        v380,
        v400,
        v403,
        v406,
        v417,
        v423,
        v439,
        v441,
        v449,
        v456,
        v464,
        v469,
        v471,
        v473,
        v476,
        v477,
        v479,
        v485,
        v489,
        v493,
        v494,
        v495,
        v498,
        v501,
        v502,
        v505,
        v506,
    ) = {
        let v338: f64 = v337 * v317;
        let v339: f64 = v336 + v338;
        let v340: f64 = params[69];
        let v341: f64 = v318 - v255;
        let v342: f64 = v340 * v341;
        let v343: f64 = v339 + v342;
        let v344: f64 = v317 * v343;
        let v345: f64 = v322 * v328;
        let v346: f64 = params[67];
        let v347: f64 = v346 * v317;
        let v348: f64 = v345 + v347;
        let v349: f64 = v337 * v341;
        let v350: f64 = v348 + v349;
        let v351: f64 = v341 * v350;
        let v352: f64 = v344 - v351;
        let v353: f64 = v335 + v352;
        let v354: f64 = params[62];
        let v355: f64 = 0.088_f64;
        let v356: f64 = v355 * v255;
        let v357: f64 = v266 * v356;
        let v358: f64 = v355 * v184;
        let v359: f64 = v357 - v358;
        let v360: f64 = v304 + v359;
        let v361: f64 = v354 * v360;
        let v362: f64 = params[63];
        let v363: f64 = v355 * v268;
        let v364: f64 = v355 * v279;
        let v365: f64 = v266 * v364;
        let v366: f64 = v363 + v365;
        let v367: f64 = v242 + v366;
        let v368: f64 = v309 * v367;
        let v369: f64 = v247 * v302;
        let v370: f64 = v250 * v221;
        let v371: f64 = v369 + v370;
        let v372: f64 = v255 * v356;
        let v373: f64 = v279 * v364;
        let v374: f64 = v372 + v373;
        let v375: f64 = v371 - v374;
        let v376: f64 = v312 * v375;
        let v377: f64 = v368 - v376;
        let v378: f64 = v362 * v377;
        let v379: f64 = v361 + v378;
        let v380: f64 = v353 - v379;
        let v381: f64 = v309 * v380;
        let v382: f64 = v322 * v320;
        let v383: f64 = v346 * v330;
        let v384: f64 = v382 - v383;
        let v385: f64 = v337 * v268;
        let v386: f64 = v384 + v385;
        let v387: f64 = v310 * v328;
        let v388: f64 = v322 * v317;
        let v389: f64 = v387 + v388;
        let v390: f64 = v333 * v341;
        let v391: f64 = v389 + v390;
        let v392: f64 = v341 * v391;
        let v393: f64 = v328 * v343;
        let v394: f64 = v392 - v393;
        let v395: f64 = v386 + v394;
        let v396: f64 = v309 * v375;
        let v397: f64 = v312 * v367;
        let v398: f64 = v396 + v397;
        let v399: f64 = v362 * v398;
        let v400: f64 = params[61];
        let v401: f64 = v400 * v360;
        let v402: f64 = v399 + v401;
        let v403: f64 = v395 + v402;
        let v404: f64 = v312 * v403;
        let v405: f64 = v381 - v404;
        let v406: f64 = v307 + v405;
        let v407: f64 = v247 * v406;
        let v408: f64 = v260 * v258;
        let v409: f64 = v284 * v268;
        let v410: f64 = v408 - v409;
        let v411: f64 = v275 * v184;
        let v412: f64 = v410 - v411;
        let v413: f64 = v248 * v266;
        let v414: f64 = v260 * v255;
        let v415: f64 = v413 + v414;
        let v416: f64 = v271 * v279;
        let v417: f64 = v415 + v416;
        let v418: f64 = v279 * v417;
        let v419: f64 = v266 * v281;
        let v420: f64 = v418 - v419;
        let v421: f64 = v412 + v420;
        let v422: f64 = v294 * v371;
        let v423: f64 = params[51];
        let v424: f64 = v423 * v242;
        let v425: f64 = v422 - v424;
        let v426: f64 = v421 + v425;
        let v427: f64 = v333 * v320;
        let v428: f64 = v337 * v330;
        let v429: f64 = v427 - v428;
        let v430: f64 = v340 * v268;
        let v431: f64 = v429 + v430;
        let v432: f64 = v328 * v350;
        let v433: f64 = v317 * v391;
        let v434: f64 = v432 - v433;
        let v435: f64 = v431 + v434;
        let v436: f64 = v400 * v377;
        let v437: f64 = v354 * v398;
        let v438: f64 = v436 - v437;
        let v439: f64 = v435 + v438;
        let v440: f64 = v426 - v439;
        let v441: f64 = params[60];
        let v442: f64 = v441 * v398;
        let v443: f64 = v328 * v354;
        let v444: f64 = v317 * v400;
        let v445: f64 = v443 - v444;
        let v446: f64 = v317 * v445;
        let v447: f64 = v341 * v400;
        let v448: f64 = v328 * v362;
        let v449: f64 = v447 - v448;
        let v450: f64 = v341 * v449;
        let v451: f64 = v446 - v450;
        let v452: f64 = v330 * v362;
        let v453: f64 = v268 * v354;
        let v454: f64 = v452 + v453;
        let v455: f64 = v451 - v454;
        let v456: f64 = v442 + v455;
        let v457: f64 = v312 * v456;
        let v458: f64 = v441 * v377;
        let v459: f64 = v268 * v400;
        let v460: f64 = v320 * v362;
        let v461: f64 = v459 - v460;
        let v462: f64 = v317 * v362;
        let v463: f64 = v341 * v354;
        let v464: f64 = v462 - v463;
        let v465: f64 = v341 * v464;
        let v466: f64 = v328 * v445;
        let v467: f64 = v465 - v466;
        let v468: f64 = v461 + v467;
        let v469: f64 = v458 + v468;
        let v470: f64 = v309 * v469;
        let v471: f64 = v457 + v470;
        let v472: f64 = v355 * v471;
        let v473: f64 = v440 - v472;
        let v474: f64 = v250 * v473;
        let v475: f64 = v407 - v474;
        let v476: f64 = v245 + v475;
        let v477: f64 = params[40];
        let v478: f64 = v477 * v242;
        let v479: f64 = params[41];
        let v480: f64 = v111 * v479;
        let v481: f64 = v174 * v223;
        let v482: f64 = v480 + v481;
        let v483: f64 = v171 * v223;
        let v484: f64 = v195 * v208;
        let v485: f64 = v483 + v484;
        let v486: f64 = v195 * v485;
        let v487: f64 = v182 * v208;
        let v488: f64 = v171 * v479;
        let v489: f64 = v487 + v488;
        let v490: f64 = v182 * v489;
        let v491: f64 = v486 + v490;
        let v492: f64 = v482 + v491;
        let v493: f64 = v478 + v492;
        let v494: f64 = params[50];
        let v495: f64 = v494 * v242;
        let v496: f64 = v258 * v292;
        let v497: f64 = v268 * v423;
        let v498: f64 = v496 + v497;
        let v499: f64 = v279 * v423;
        let v500: f64 = v266 * v294;
        let v501: f64 = v499 - v500;
        let v502: f64 = v266 * v501;
        let v503: f64 = v255 * v294;
        let v504: f64 = v279 * v292;
        let v505: f64 = v503 - v504;
        let v506: f64 = v255 * v505;
        (
            v354,
            v355,
            v360,
            v371,
            v380,
            v400,
            v403,
            v406,
            v417,
            v423,
            v439,
            v441,
            v449,
            v456,
            v464,
            v469,
            v471,
            v473,
            v476,
            v477,
            v479,
            v485,
            v489,
            v493,
            v494,
            v495,
            v498,
            v501,
            v502,
            v505,
            v506,
        )
    };
    let (
        v511,
        v513,
        v560,
        v569,
        v589,
        v600,
        v603,
        v605,
        v608,
        v619,
        v625,
        v645,
        v649,
        v651,
        v654,
        v655,
        v662,
        v664,
        v671,
        v674,
        v675,
    ) = {
        let v507: f64 = v502 - v506;
        let v508: f64 = v498 + v507;
        let v509: f64 = v495 + v508;
        let v510: f64 = v509 + v471;
        let v511: f64 = v493 + v510;
        let v512: f64 = v215 * v511;
        let v513: f64 = v476 + v512;
        let v514: f64 = v163 * v513;
        let v515: f64 = v176 * v174;
        let v516: f64 = v200 * v184;
        let v517: f64 = v515 + v516;
        let v518: f64 = v191 * v111;
        let v519: f64 = v517 - v518;
        let v520: f64 = v164 * v182;
        let v521: f64 = v176 * v171;
        let v522: f64 = v520 - v521;
        let v523: f64 = v187 * v195;
        let v524: f64 = v522 + v523;
        let v525: f64 = v195 * v524;
        let v526: f64 = v182 * v197;
        let v527: f64 = v525 - v526;
        let v528: f64 = v519 + v527;
        let v529: f64 = v223 * v302;
        let v530: f64 = v479 * v221;
        let v531: f64 = v529 - v530;
        let v532: f64 = v528 + v531;
        let v533: f64 = v271 * v258;
        let v534: f64 = v275 * v268;
        let v535: f64 = v533 - v534;
        let v536: f64 = v278 * v184;
        let v537: f64 = v535 - v536;
        let v538: f64 = v266 * v288;
        let v539: f64 = v255 * v417;
        let v540: f64 = v538 - v539;
        let v541: f64 = v537 + v540;
        let v542: f64 = v423 * v304;
        let v543: f64 = v292 * v371;
        let v544: f64 = v542 - v543;
        let v545: f64 = v541 + v544;
        let v546: f64 = v312 * v380;
        let v547: f64 = v309 * v403;
        let v548: f64 = v546 + v547;
        let v549: f64 = v545 + v548;
        let v550: f64 = v320 * v354;
        let v551: f64 = v330 * v400;
        let v552: f64 = v550 + v551;
        let v553: f64 = v328 * v449;
        let v554: f64 = v317 * v464;
        let v555: f64 = v553 - v554;
        let v556: f64 = v552 + v555;
        let v557: f64 = v441 * v360;
        let v558: f64 = v556 - v557;
        let v559: f64 = v355 * v558;
        let v560: f64 = v549 - v559;
        let v561: f64 = v532 - v560;
        let v562: f64 = v477 * v302;
        let v563: f64 = v184 * v223;
        let v564: f64 = v111 * v208;
        let v565: f64 = v563 + v564;
        let v566: f64 = v171 * v489;
        let v567: f64 = v195 * v479;
        let v568: f64 = v182 * v223;
        let v569: f64 = v567 - v568;
        let v570: f64 = v195 * v569;
        let v571: f64 = v566 + v570;
        let v572: f64 = v565 - v571;
        let v573: f64 = v562 + v572;
        let v574: f64 = v494 * v371;
        let v575: f64 = v184 * v292;
        let v576: f64 = v268 * v294;
        let v577: f64 = v575 - v576;
        let v578: f64 = v266 * v292;
        let v579: f64 = v255 * v423;
        let v580: f64 = v578 - v579;
        let v581: f64 = v255 * v580;
        let v582: f64 = v279 * v501;
        let v583: f64 = v581 - v582;
        let v584: f64 = v577 + v583;
        let v585: f64 = v574 + v584;
        let v586: f64 = v309 * v456;
        let v587: f64 = v312 * v469;
        let v588: f64 = v586 - v587;
        let v589: f64 = v585 + v588;
        let v590: f64 = v247 * v589;
        let v591: f64 = v494 * v304;
        let v592: f64 = v279 * v505;
        let v593: f64 = v266 * v580;
        let v594: f64 = v592 - v593;
        let v595: f64 = v184 * v423;
        let v596: f64 = v258 * v294;
        let v597: f64 = v595 + v596;
        let v598: f64 = v594 - v597;
        let v599: f64 = v591 + v598;
        let v600: f64 = v599 - v558;
        let v601: f64 = v250 * v600;
        let v602: f64 = v590 - v601;
        let v603: f64 = v573 + v602;
        let v604: f64 = v215 * v603;
        let v605: f64 = v561 + v604;
        let v606: f64 = v166 * v605;
        let v607: f64 = v514 - v606;
        let v608: f64 = v161 + v607;
        let v609: f64 = v90 * v608;
        let v610: f64 = v103 * v101;
        let v611: f64 = v127 * v111;
        let v612: f64 = v610 - v611;
        let v613: f64 = v118 * v50;
        let v614: f64 = v612 - v613;
        let v615: f64 = v91 * v109;
        let v616: f64 = v103 * v98;
        let v617: f64 = v615 + v616;
        let v618: f64 = v114 * v122;
        let v619: f64 = v617 + v618;
        let v620: f64 = v122 * v619;
        let v621: f64 = v109 * v124;
        let v622: f64 = v620 - v621;
        let v623: f64 = v614 + v622;
        let v624: f64 = v143 * v226;
        let v625: f64 = params[31];
        let v626: f64 = v625 * v141;
        let v627: f64 = v624 + v626;
        let v628: f64 = v623 + v627;
        let v629: f64 = v187 * v174;
        let v630: f64 = v191 * v184;
        let v631: f64 = v629 + v630;
        let v632: f64 = v194 * v111;
        let v633: f64 = v631 - v632;
        let v634: f64 = v182 * v204;
        let v635: f64 = v171 * v524;
        let v636: f64 = v634 + v635;
        let v637: f64 = v633 + v636;
        let v638: f64 = v479 * v242;
        let v639: f64 = v208 * v302;
        let v640: f64 = v638 + v639;
        let v641: f64 = v637 - v640;
        let v642: f64 = v250 * v406;
        let v643: f64 = v247 * v473;
        let v644: f64 = v642 + v643;
        let v645: f64 = v641 + v644;
        let v646: f64 = v628 + v645;
        let v647: f64 = v163 * v511;
        let v648: f64 = v166 * v603;
        let v649: f64 = v647 - v648;
        let v650: f64 = v209 * v649;
        let v651: f64 = v646 - v650;
        let v652: f64 = v93 * v651;
        let v653: f64 = v609 - v652;
        let v654: f64 = v88 + v653;
        let v655: f64 = params[20];
        let v656: f64 = v655 * v85;
        let v657: f64 = v38 * v82;
        let v658: f64 = v61 * v74;
        let v659: f64 = v657 - v658;
        let v660: f64 = v61 * v659;
        let v661: f64 = v48 * v74;
        let v662: f64 = params[21];
        let v663: f64 = v38 * v662;
        let v664: f64 = v661 - v663;
        let v665: f64 = v48 * v664;
        let v666: f64 = v660 - v665;
        let v667: f64 = v6 * v662;
        let v668: f64 = v42 * v82;
        let v669: f64 = v667 + v668;
        let v670: f64 = v666 - v669;
        let v671: f64 = v656 + v670;
        let v672: f64 = v101 * v135;
        let v673: f64 = v111 * v625;
        let v674: f64 = v672 + v673;
        let v675: f64 = v122 * v625;
        (
            v511,
            v513,
            v560,
            v569,
            v589,
            v600,
            v603,
            v605,
            v608,
            v619,
            v625,
            v645,
            v649,
            v651,
            v654,
            v655,
            v662,
            v664,
            v671,
            v674,
            v675,
        )
    };
    let (v742, v827, v831, v842) = {
        let v676: f64 = v109 * v143;
        let v677: f64 = v675 - v676;
        let v678: f64 = v109 * v677;
        let v679: f64 = v98 * v143;
        let v680: f64 = v122 * v135;
        let v681: f64 = v679 - v680;
        let v682: f64 = v98 * v681;
        let v683: f64 = v678 - v682;
        let v684: f64 = v674 + v683;
        let v685: f64 = params[30];
        let v686: f64 = v685 * v141;
        let v687: f64 = v684 - v686;
        let v688: f64 = v687 + v649;
        let v689: f64 = v671 - v688;
        let v690: f64 = v75 * v689;
        let v691: f64 = v654 - v690;
        let v692: f64 = v33 * v691;
        let v693: f64 = v44 * v42;
        let v694: f64 = v66 * v50;
        let v695: f64 = v693 + v694;
        let v696: f64 = v57 * v6;
        let v697: f64 = v695 - v696;
        let v698: f64 = v34 * v48;
        let v699: f64 = v44 * v38;
        let v700: f64 = v698 + v699;
        let v701: f64 = v53 * v61;
        let v702: f64 = v700 + v701;
        let v703: f64 = v61 * v702;
        let v704: f64 = v48 * v63;
        let v705: f64 = v703 - v704;
        let v706: f64 = v697 + v705;
        let v707: f64 = v82 * v152;
        let v708: f64 = v662 * v80;
        let v709: f64 = v707 + v708;
        let v710: f64 = v706 + v709;
        let v711: f64 = v114 * v101;
        let v712: f64 = v118 * v111;
        let v713: f64 = v711 - v712;
        let v714: f64 = v121 * v50;
        let v715: f64 = v713 - v714;
        let v716: f64 = v109 * v131;
        let v717: f64 = v98 * v619;
        let v718: f64 = v716 - v717;
        let v719: f64 = v715 + v718;
        let v720: f64 = v625 * v158;
        let v721: f64 = v135 * v226;
        let v722: f64 = v720 - v721;
        let v723: f64 = v719 + v722;
        let v724: f64 = v166 * v513;
        let v725: f64 = v163 * v605;
        let v726: f64 = v724 + v725;
        let v727: f64 = v723 - v726;
        let v728: f64 = v477 * v221;
        let v729: f64 = v174 * v208;
        let v730: f64 = v184 * v479;
        let v731: f64 = v729 - v730;
        let v732: f64 = v182 * v569;
        let v733: f64 = v171 * v485;
        let v734: f64 = v732 - v733;
        let v735: f64 = v731 + v734;
        let v736: f64 = v728 + v735;
        let v737: f64 = v250 * v589;
        let v738: f64 = v247 * v600;
        let v739: f64 = v737 + v738;
        let v740: f64 = v736 + v739;
        let v741: f64 = v209 * v740;
        let v742: f64 = v727 + v741;
        let v743: f64 = v710 - v742;
        let v744: f64 = v685 * v226;
        let v745: f64 = v50 * v135;
        let v746: f64 = v111 * v143;
        let v747: f64 = v745 - v746;
        let v748: f64 = v109 * v135;
        let v749: f64 = v98 * v625;
        let v750: f64 = v748 - v749;
        let v751: f64 = v98 * v750;
        let v752: f64 = v122 * v677;
        let v753: f64 = v751 - v752;
        let v754: f64 = v747 + v753;
        let v755: f64 = v744 + v754;
        let v756: f64 = v163 * v603;
        let v757: f64 = v166 * v511;
        let v758: f64 = v756 + v757;
        let v759: f64 = v755 + v758;
        let v760: f64 = v93 * v759;
        let v761: f64 = v685 * v158;
        let v762: f64 = v122 * v681;
        let v763: f64 = v109 * v750;
        let v764: f64 = v762 - v763;
        let v765: f64 = v50 * v625;
        let v766: f64 = v101 * v143;
        let v767: f64 = v765 + v766;
        let v768: f64 = v764 - v767;
        let v769: f64 = v761 + v768;
        let v770: f64 = v769 + v740;
        let v771: f64 = v90 * v770;
        let v772: f64 = v760 + v771;
        let v773: f64 = v136 * v772;
        let v774: f64 = v743 - v773;
        let v775: f64 = v655 * v152;
        let v776: f64 = v50 * v82;
        let v777: f64 = v6 * v74;
        let v778: f64 = v776 + v777;
        let v779: f64 = v38 * v664;
        let v780: f64 = v61 * v662;
        let v781: f64 = v48 * v82;
        let v782: f64 = v780 - v781;
        let v783: f64 = v61 * v782;
        let v784: f64 = v779 - v783;
        let v785: f64 = v778 + v784;
        let v786: f64 = v775 + v785;
        let v787: f64 = v90 * v759;
        let v788: f64 = v93 * v770;
        let v789: f64 = v787 - v788;
        let v790: f64 = v786 + v789;
        let v791: f64 = v75 * v790;
        let v792: f64 = v774 + v791;
        let v793: f64 = v35 * v792;
        let v794: f64 = v692 - v793;
        let v795: f64 = v31 + v794;
        let v796: f64 = v1 * v795;
        let v797: f64 = v25 * v6;
        let v798: f64 = v2 * v11;
        let v799: f64 = v797 - v798;
        let v800: f64 = v16 * v5;
        let v801: f64 = v8 * v4;
        let v802: f64 = v2 * v10;
        let v803: f64 = v801 + v802;
        let v804: f64 = v800 - v803;
        let v805: f64 = v5 * v804;
        let v806: f64 = v4 * v21;
        let v807: f64 = v805 + v806;
        let v808: f64 = v799 + v807;
        let v809: f64 = v53 * v42;
        let v810: f64 = v57 * v50;
        let v811: f64 = v809 + v810;
        let v812: f64 = v60 * v6;
        let v813: f64 = v811 - v812;
        let v814: f64 = v48 * v70;
        let v815: f64 = v38 * v702;
        let v816: f64 = v814 - v815;
        let v817: f64 = v813 + v816;
        let v818: f64 = v662 * v85;
        let v819: f64 = v74 * v152;
        let v820: f64 = v818 - v819;
        let v821: f64 = v817 + v820;
        let v822: f64 = v93 * v608;
        let v823: f64 = v90 * v651;
        let v824: f64 = v822 + v823;
        let v825: f64 = v821 + v824;
        let v826: f64 = v136 * v688;
        let v827: f64 = v825 - v826;
        let v828: f64 = v808 - v827;
        let v829: f64 = v9 * v828;
        let v830: f64 = v796 + v829;
        let v831: f64 = -v830;
        let v832: f64 = v18 * v6;
        let v833: f64 = v16 * v11;
        let v834: f64 = v832 - v833;
        let v835: f64 = v10 * v804;
        let v836: f64 = v4 * v28;
        let v837: f64 = v835 - v836;
        let v838: f64 = v834 + v837;
        let v839: f64 = v35 * v691;
        let v840: f64 = v33 * v792;
        let v841: f64 = v839 + v840;
        let v842: f64 = v838 + v841;
        (v742, v827, v831, v842)
    };
    [v831, v842, v827, v742, v645, v560, v439]
}
/// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
///
/// # Inputs
///
/// - `q: &[f64; 7]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 70]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `gravity: [f64; 7]`: g(q), joint torques (N m) or forces (N) that hold the robot still
///
/// Operation count: 178 floating-point operations, 12 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn gravity(q: &[f64; 7], params: &[f64; 70]) -> [f64; 7] {
    let (
        v0,
        v1,
        v13,
        v27,
        v29,
        v30,
        v42,
        v48,
        v57,
        v58,
        v60,
        v61,
        v62,
        v64,
        v67,
        v72,
        v74,
        v77,
        v79,
        v81,
        v83,
        v86,
        v89,
        v92,
        v95,
        v96,
        v98,
        v99,
        v103,
        v104,
        v110,
        v111,
        v141,
    ) = {
        let v0: f64 = 0.0_f64;
        let v1: f64 = 9.81_f64;
        let v2: f64 = params[12];
        let v3: f64 = v1 * v2;
        let v4: f64 = 3.09996_f64;
        let v5: f64 = params[60];
        let v6: f64 = v4 * v5;
        let v7: f64 = params[50];
        let v8: f64 = v4 * v7;
        let v9: f64 = v6 + v8;
        let v10: f64 = params[40];
        let v11: f64 = v4 * v10;
        let v12: f64 = v9 + v11;
        let v13: f64 = params[30];
        let v14: f64 = v4 * v13;
        let v15: f64 = v12 + v14;
        let v16: f64 = params[23];
        let v17: f64 = v1 * v16;
        let v18: f64 = v15 + v17;
        let v19: f64 = params[20];
        let v20: f64 = v4 * v19;
        let v21: f64 = v18 + v20;
        let v22: f64 = v3 - v21;
        let v23: f64 = params[63];
        let v24: f64 = v1 * v23;
        let v25: f64 = params[52];
        let v26: f64 = v1 * v25;
        let v27: f64 = v24 - v26;
        let v28: f64 = q[5];
        let (v60, v29): (f64, f64) = ::armdyn_runtime::libm::sincos(v28);
        let v30: f64 = v27 * v29;
        let v31: f64 = 3.76704_f64;
        let v32: f64 = v31 * v5;
        let v33: f64 = v31 * v7;
        let v34: f64 = v32 + v33;
        let v35: f64 = params[43];
        let v36: f64 = v1 * v35;
        let v37: f64 = v34 + v36;
        let v38: f64 = v31 * v10;
        let v39: f64 = v37 + v38;
        let v40: f64 = params[32];
        let v41: f64 = v1 * v40;
        let v42: f64 = v39 + v41;
        let v43: f64 = v30 - v42;
        let v44: f64 = params[62];
        let v45: f64 = v1 * v44;
        let v46: f64 = q[6];
        let (v47, v56): (f64, f64) = ::armdyn_runtime::libm::sincos(v46);
        let v48: f64 = v45 * v47;
        let v49: f64 = 0.86328_f64;
        let v50: f64 = v49 * v5;
        let v51: f64 = params[51];
        let v52: f64 = v1 * v51;
        let v53: f64 = v50 + v52;
        let v54: f64 = params[61];
        let v55: f64 = v1 * v54;
        let v57: f64 = v55 * v56;
        let v58: f64 = v53 + v57;
        let v59: f64 = v48 - v58;
        let v61: f64 = v59 * v60;
        let v62: f64 = v43 + v61;
        let v63: f64 = q[3];
        let (v99, v64): (f64, f64) = ::armdyn_runtime::libm::sincos(v63);
        let v65: f64 = v62 * v64;
        let v66: f64 = v22 + v65;
        let v67: f64 = 0.809325_f64;
        let v68: f64 = v67 * v5;
        let v69: f64 = v67 * v7;
        let v70: f64 = v68 + v69;
        let v71: f64 = v67 * v10;
        let v72: f64 = v70 + v71;
        let v73: f64 = params[31];
        let v74: f64 = v1 * v73;
        let v75: f64 = v72 - v74;
        let v76: f64 = params[42];
        let v77: f64 = v1 * v76;
        let v78: f64 = params[53];
        let v79: f64 = v1 * v78;
        let v80: f64 = v77 - v79;
        let v81: f64 = v45 * v56;
        let v82: f64 = v80 - v81;
        let v83: f64 = v55 * v47;
        let v84: f64 = v82 - v83;
        let v85: f64 = q[4];
        let (v86, v96): (f64, f64) = ::armdyn_runtime::libm::sincos(v85);
        let v87: f64 = v84 * v86;
        let v88: f64 = v75 + v87;
        let v89: f64 = v26 - v24;
        let v90: f64 = v89 * v60;
        let v91: f64 = params[41];
        let v92: f64 = v1 * v91;
        let v93: f64 = v90 - v92;
        let v94: f64 = v59 * v29;
        let v95: f64 = v93 + v94;
        let v97: f64 = v95 * v96;
        let v98: f64 = v88 + v97;
        let v100: f64 = v98 * v99;
        let v101: f64 = v66 + v100;
        let v102: f64 = q[1];
        let (v103, v141): (f64, f64) = ::armdyn_runtime::libm::sincos(v102);
        let v104: f64 = v101 * v103;
        let v105: f64 = params[22];
        let v106: f64 = v1 * v105;
        let v107: f64 = params[33];
        let v108: f64 = v1 * v107;
        let v109: f64 = v106 - v108;
        let v110: f64 = v84 * v96;
        let v111: f64 = v109 + v110;
        (
            v0,
            v1,
            v13,
            v27,
            v29,
            v30,
            v42,
            v48,
            v57,
            v58,
            v60,
            v61,
            v62,
            v64,
            v67,
            v72,
            v74,
            v77,
            v79,
            v81,
            v83,
            v86,
            v89,
            v92,
            v95,
            v96,
            v98,
            v99,
            v103,
            v104,
            v110,
            v111,
            v141,
        )
    };
    let (v143, v159, v167, v180, v198, v223) = {
        let v112: f64 = v27 * v60;
        let v113: f64 = v92 + v112;
        let v114: f64 = v58 - v48;
        let v115: f64 = v114 * v29;
        let v116: f64 = v113 + v115;
        let v117: f64 = v116 * v86;
        let v118: f64 = v111 + v117;
        let v119: f64 = q[2];
        let (v120, v138): (f64, f64) = ::armdyn_runtime::libm::sincos(v119);
        let v121: f64 = v118 * v120;
        let v122: f64 = params[11];
        let v123: f64 = v1 * v122;
        let v124: f64 = v121 - v123;
        let v125: f64 = v89 * v29;
        let v126: f64 = v42 + v125;
        let v127: f64 = v114 * v60;
        let v128: f64 = v126 + v127;
        let v129: f64 = v128 * v99;
        let v130: f64 = v67 * v13;
        let v131: f64 = v72 + v130;
        let v132: f64 = params[21];
        let v133: f64 = v1 * v132;
        let v134: f64 = v131 + v133;
        let v135: f64 = v129 - v134;
        let v136: f64 = v98 * v64;
        let v137: f64 = v135 + v136;
        let v139: f64 = v137 * v138;
        let v140: f64 = v124 + v139;
        let v142: f64 = v140 * v141;
        let v143: f64 = v104 + v142;
        let v144: f64 = v118 * v138;
        let v145: f64 = v62 * v99;
        let v146: f64 = v134 + v145;
        let v147: f64 = v74 - v72;
        let v148: f64 = v79 - v77;
        let v149: f64 = v148 + v81;
        let v150: f64 = v149 + v83;
        let v151: f64 = v150 * v86;
        let v152: f64 = v147 + v151;
        let v153: f64 = v116 * v96;
        let v154: f64 = v152 + v153;
        let v155: f64 = v154 * v64;
        let v156: f64 = v146 + v155;
        let v157: f64 = v156 * v120;
        let v158: f64 = v144 + v157;
        let v159: f64 = v158 * v103;
        let v160: f64 = v145 + v155;
        let v161: f64 = v160 * v141;
        let v162: f64 = v128 * v64;
        let v163: f64 = v154 * v99;
        let v164: f64 = v162 + v163;
        let v165: f64 = v164 * v138;
        let v166: f64 = v165 * v103;
        let v167: f64 = v161 + v166;
        let v168: f64 = v150 * v96;
        let v169: f64 = v95 * v86;
        let v170: f64 = v168 + v169;
        let v171: f64 = v170 * v99;
        let v172: f64 = v171 * v141;
        let v173: f64 = v110 + v117;
        let v174: f64 = v173 * v64;
        let v175: f64 = v174 * v138;
        let v176: f64 = v151 + v153;
        let v177: f64 = v176 * v120;
        let v178: f64 = v175 + v177;
        let v179: f64 = v178 * v103;
        let v180: f64 = v172 + v179;
        let v181: f64 = v112 + v115;
        let v182: f64 = v181 * v64;
        let v183: f64 = v30 + v61;
        let v184: f64 = v183 * v96;
        let v185: f64 = v184 * v99;
        let v186: f64 = v182 + v185;
        let v187: f64 = v186 * v141;
        let v188: f64 = v183 * v86;
        let v189: f64 = v188 * v120;
        let v190: f64 = v125 + v127;
        let v191: f64 = v190 * v96;
        let v192: f64 = v191 * v64;
        let v193: f64 = v181 * v99;
        let v194: f64 = v192 + v193;
        let v195: f64 = v194 * v138;
        let v196: f64 = v189 + v195;
        let v197: f64 = v196 * v103;
        let v198: f64 = v187 + v197;
        let v199: f64 = v57 - v48;
        let v200: f64 = v199 * v86;
        let v201: f64 = v81 + v83;
        let v202: f64 = v201 * v29;
        let v203: f64 = v202 * v96;
        let v204: f64 = v200 - v203;
        let v205: f64 = v204 * v99;
        let v206: f64 = v201 * v60;
        let v207: f64 = v206 * v64;
        let v208: f64 = v205 - v207;
        let v209: f64 = v208 * v141;
        let v210: f64 = v48 - v57;
        let v211: f64 = v210 * v96;
        let v212: f64 = v202 * v86;
        let v213: f64 = v211 - v212;
        let v214: f64 = v213 * v120;
        let v215: f64 = v210 * v86;
        let v216: f64 = v203 + v215;
        let v217: f64 = v216 * v64;
        let v218: f64 = v206 * v99;
        let v219: f64 = v217 - v218;
        let v220: f64 = v219 * v138;
        let v221: f64 = v214 + v220;
        let v222: f64 = v221 * v103;
        let v223: f64 = v209 + v222;
        (v143, v159, v167, v180, v198, v223)
    };
    [v0, v143, v159, v167, v180, v198, v223]
}
/// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
///
/// # Inputs
///
/// - `q: &[f64; 7]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 7]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 7]`: joint accelerations qdd (rad/s^2 or m/s^2)
/// - `params: &[f64; 70]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `tau: [f64; 7]`: joint torques (N m) or forces (N), no external wrench
///
/// Operation count: 792 floating-point operations, 12 trig calls.
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
    q: &[f64; 7],
    qd: &[f64; 7],
    qdd: &[f64; 7],
    params: &[f64; 70],
) -> [f64; 7] {
    let (
        v2,
        v4,
        v5,
        v7,
        v8,
        v10,
        v12,
        v14,
        v16,
        v18,
        v21,
        v22,
        v25,
        v28,
        v31,
        v35,
        v38,
        v42,
        v44,
        v46,
        v48,
        v49,
        v50,
        v56,
        v59,
        v61,
        v67,
        v69,
        v72,
        v74,
        v78,
        v81,
        v82,
        v84,
        v87,
        v91,
        v95,
        v96,
        v97,
        v102,
        v104,
        v105,
        v110,
        v113,
        v115,
        v116,
        v118,
        v123,
        v126,
        v128,
        v134,
        v136,
        v139,
        v141,
        v145,
        v148,
        v149,
        v151,
        v154,
        v158,
        v161,
        v162,
        v163,
        v165,
        v168,
        v169,
        v170,
        v171,
        v175,
        v176,
        v177,
    ) = {
        let v0: f64 = params[9];
        let v1: f64 = qdd[0];
        let v2: f64 = v0 * v1;
        let v3: f64 = q[1];
        let (v4, v10): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
        let v5: f64 = params[15];
        let v6: f64 = qd[0];
        let v7: f64 = v4 * v6;
        let v8: f64 = qd[1];
        let v9: f64 = v7 * v8;
        let v11: f64 = v10 * v1;
        let v12: f64 = v9 - v11;
        let v13: f64 = v5 * v12;
        let v14: f64 = params[14];
        let v15: f64 = v4 * v1;
        let v16: f64 = v10 * v6;
        let v17: f64 = v16 * v8;
        let v18: f64 = v15 + v17;
        let v19: f64 = v14 * v18;
        let v20: f64 = v13 - v19;
        let v21: f64 = params[16];
        let v22: f64 = qdd[1];
        let v23: f64 = v21 * v22;
        let v24: f64 = v20 + v23;
        let v25: f64 = params[19];
        let v26: f64 = v25 * v8;
        let v27: f64 = v21 * v7;
        let v28: f64 = params[18];
        let v29: f64 = v28 * v16;
        let v30: f64 = v27 + v29;
        let v31: f64 = v26 - v30;
        let v32: f64 = v16 * v31;
        let v33: f64 = v28 * v8;
        let v34: f64 = v5 * v7;
        let v35: f64 = params[17];
        let v36: f64 = v35 * v16;
        let v37: f64 = v34 + v36;
        let v38: f64 = v33 - v37;
        let v39: f64 = v8 * v38;
        let v40: f64 = v32 + v39;
        let v41: f64 = v24 - v40;
        let v42: f64 = params[13];
        let v43: f64 = 9.81_f64;
        let v44: f64 = v43 * v10;
        let v45: f64 = v42 * v44;
        let v46: f64 = v41 + v45;
        let v47: f64 = q[2];
        let (v50, v48): (f64, f64) = ::armdyn_runtime::libm::sincos(v47);
        let v49: f64 = params[24];
        let v51: f64 = v50 * v22;
        let v52: f64 = v48 * v18;
        let v53: f64 = v51 - v52;
        let v54: f64 = v50 * v7;
        let v55: f64 = v48 * v8;
        let v56: f64 = v54 + v55;
        let v57: f64 = qd[2];
        let v58: f64 = v56 * v57;
        let v59: f64 = v53 + v58;
        let v60: f64 = v49 * v59;
        let v61: f64 = params[25];
        let v62: f64 = v50 * v18;
        let v63: f64 = v48 * v22;
        let v64: f64 = v62 + v63;
        let v65: f64 = v50 * v8;
        let v66: f64 = v48 * v7;
        let v67: f64 = v65 - v66;
        let v68: f64 = v67 * v57;
        let v69: f64 = v64 - v68;
        let v70: f64 = v61 * v69;
        let v71: f64 = v60 + v70;
        let v72: f64 = params[26];
        let v73: f64 = qdd[2];
        let v74: f64 = v73 - v12;
        let v75: f64 = v72 * v74;
        let v76: f64 = v71 + v75;
        let v77: f64 = v72 * v67;
        let v78: f64 = params[28];
        let v79: f64 = v78 * v56;
        let v80: f64 = v77 + v79;
        let v81: f64 = params[29];
        let v82: f64 = v16 + v57;
        let v83: f64 = v81 * v82;
        let v84: f64 = v80 + v83;
        let v85: f64 = v56 * v84;
        let v86: f64 = v61 * v67;
        let v87: f64 = params[27];
        let v88: f64 = v87 * v56;
        let v89: f64 = v86 + v88;
        let v90: f64 = v78 * v82;
        let v91: f64 = v89 + v90;
        let v92: f64 = v82 * v91;
        let v93: f64 = v85 - v92;
        let v94: f64 = v76 + v93;
        let v95: f64 = params[22];
        let v96: f64 = 0.316_f64;
        let v97: f64 = v96 * v67;
        let v98: f64 = v67 * v97;
        let v99: f64 = v96 * v56;
        let v100: f64 = v56 * v99;
        let v101: f64 = v98 + v100;
        let v102: f64 = v44 - v101;
        let v103: f64 = v95 * v102;
        let v104: f64 = params[23];
        let v105: f64 = v43 * v4;
        let v106: f64 = v50 * v105;
        let v107: f64 = v82 * v99;
        let v108: f64 = v96 * v59;
        let v109: f64 = v107 - v108;
        let v110: f64 = v106 + v109;
        let v111: f64 = v104 * v110;
        let v112: f64 = v103 - v111;
        let v113: f64 = v94 + v112;
        let v114: f64 = q[3];
        let (v118, v115): (f64, f64) = ::armdyn_runtime::libm::sincos(v114);
        let v116: f64 = params[34];
        let v117: f64 = v115 * v59;
        let v119: f64 = v118 * v74;
        let v120: f64 = v117 + v119;
        let v121: f64 = v115 * v82;
        let v122: f64 = v118 * v67;
        let v123: f64 = v121 - v122;
        let v124: f64 = qd[3];
        let v125: f64 = v123 * v124;
        let v126: f64 = v120 + v125;
        let v127: f64 = v116 * v126;
        let v128: f64 = params[35];
        let v129: f64 = v115 * v74;
        let v130: f64 = v118 * v59;
        let v131: f64 = v129 - v130;
        let v132: f64 = v115 * v67;
        let v133: f64 = v118 * v82;
        let v134: f64 = v132 + v133;
        let v135: f64 = v134 * v124;
        let v136: f64 = v131 - v135;
        let v137: f64 = v128 * v136;
        let v138: f64 = v127 + v137;
        let v139: f64 = params[36];
        let v140: f64 = qdd[3];
        let v141: f64 = v140 - v69;
        let v142: f64 = v139 * v141;
        let v143: f64 = v138 + v142;
        let v144: f64 = v139 * v134;
        let v145: f64 = params[38];
        let v146: f64 = v145 * v123;
        let v147: f64 = v144 + v146;
        let v148: f64 = params[39];
        let v149: f64 = v124 - v56;
        let v150: f64 = v148 * v149;
        let v151: f64 = v147 + v150;
        let v152: f64 = v123 * v151;
        let v153: f64 = v128 * v134;
        let v154: f64 = params[37];
        let v155: f64 = v154 * v123;
        let v156: f64 = v153 + v155;
        let v157: f64 = v145 * v149;
        let v158: f64 = v156 + v157;
        let v159: f64 = v149 * v158;
        let v160: f64 = v152 - v159;
        let v161: f64 = v143 + v160;
        let v162: f64 = params[32];
        let v163: f64 = 0.0825_f64;
        let v164: f64 = v163 * v74;
        let v165: f64 = v163 * v56;
        let v166: f64 = v67 * v165;
        let v167: f64 = v164 + v166;
        let v168: f64 = v110 + v167;
        let v169: f64 = v162 * v168;
        let v170: f64 = params[33];
        let v171: f64 = v163 * v82;
        let v172: f64 = v67 * v171;
        let v173: f64 = v163 * v69;
        let v174: f64 = v172 - v173;
        let v175: f64 = v102 + v174;
        let v176: f64 = v115 * v175;
        let v177: f64 = v96 * v69;
        (
            v2,
            v4,
            v5,
            v7,
            v8,
            v10,
            v12,
            v14,
            v16,
            v18,
            v21,
            v22,
            v25,
            v28,
            v31,
            v35,
            v38,
            v42,
            v44,
            v46,
            v48,
            v49,
            v50,
            v56,
            v59,
            v61,
            v67,
            v69,
            v72,
            v74,
            v78,
            v81,
            v82,
            v84,
            v87,
            v91,
            v95,
            v96,
            v97,
            v102,
            v104,
            v105,
            v110,
            v113,
            v115,
            v116,
            v118,
            v123,
            v126,
            v128,
            v134,
            v136,
            v139,
            v141,
            v145,
            v148,
            v149,
            v151,
            v154,
            v158,
            v161,
            v162,
            v163,
            v165,
            v168,
            v169,
            v170,
            v171,
            v175,
            v176,
            v177,
        )
    };
    let (
        v181,
        v187,
        v190,
        v192,
        v193,
        v195,
        v200,
        v203,
        v205,
        v211,
        v213,
        v216,
        v218,
        v222,
        v225,
        v226,
        v228,
        v231,
        v235,
        v239,
        v240,
        v246,
        v252,
        v254,
        v257,
        v273,
        v276,
        v278,
        v279,
        v281,
        v286,
        v289,
        v291,
        v297,
        v299,
        v302,
        v304,
        v308,
        v311,
        v312,
        v314,
        v317,
        v321,
        v325,
        v327,
        v335,
        v337,
        v340,
        v342,
        v343,
        v345,
        v350,
        v351,
        v353,
        v354,
        v355,
    ) = {
        let v178: f64 = v82 * v97;
        let v179: f64 = v177 + v178;
        let v180: f64 = v48 * v105;
        let v181: f64 = v179 - v180;
        let v182: f64 = v56 * v165;
        let v183: f64 = v82 * v171;
        let v184: f64 = v182 + v183;
        let v185: f64 = v181 - v184;
        let v186: f64 = v118 * v185;
        let v187: f64 = v176 - v186;
        let v188: f64 = v170 * v187;
        let v189: f64 = v169 + v188;
        let v190: f64 = v161 - v189;
        let v191: f64 = q[4];
        let (v195, v192): (f64, f64) = ::armdyn_runtime::libm::sincos(v191);
        let v193: f64 = params[44];
        let v194: f64 = v192 * v126;
        let v196: f64 = v195 * v141;
        let v197: f64 = v194 - v196;
        let v198: f64 = v195 * v134;
        let v199: f64 = v192 * v149;
        let v200: f64 = v198 + v199;
        let v201: f64 = qd[4];
        let v202: f64 = v200 * v201;
        let v203: f64 = v197 - v202;
        let v204: f64 = v193 * v203;
        let v205: f64 = params[45];
        let v206: f64 = v195 * v126;
        let v207: f64 = v192 * v141;
        let v208: f64 = v206 + v207;
        let v209: f64 = v192 * v134;
        let v210: f64 = v195 * v149;
        let v211: f64 = v209 - v210;
        let v212: f64 = v211 * v201;
        let v213: f64 = v208 + v212;
        let v214: f64 = v205 * v213;
        let v215: f64 = v204 - v214;
        let v216: f64 = params[46];
        let v217: f64 = qdd[4];
        let v218: f64 = v136 + v217;
        let v219: f64 = v216 * v218;
        let v220: f64 = v215 + v219;
        let v221: f64 = v216 * v211;
        let v222: f64 = params[48];
        let v223: f64 = v222 * v200;
        let v224: f64 = v221 - v223;
        let v225: f64 = params[49];
        let v226: f64 = v123 + v201;
        let v227: f64 = v225 * v226;
        let v228: f64 = v224 + v227;
        let v229: f64 = v200 * v228;
        let v230: f64 = v205 * v211;
        let v231: f64 = params[47];
        let v232: f64 = v231 * v200;
        let v233: f64 = v230 - v232;
        let v234: f64 = v222 * v226;
        let v235: f64 = v233 + v234;
        let v236: f64 = v226 * v235;
        let v237: f64 = v229 + v236;
        let v238: f64 = v220 - v237;
        let v239: f64 = params[42];
        let v240: f64 = -0.0825_f64;
        let v241: f64 = v240 * v141;
        let v242: f64 = v240 * v123;
        let v243: f64 = v134 * v242;
        let v244: f64 = v241 + v243;
        let v245: f64 = v187 + v244;
        let v246: f64 = 0.384_f64;
        let v247: f64 = v246 * v211;
        let v248: f64 = v211 * v247;
        let v249: f64 = v246 * v200;
        let v250: f64 = v200 * v249;
        let v251: f64 = v248 + v250;
        let v252: f64 = v245 - v251;
        let v253: f64 = v239 * v252;
        let v254: f64 = params[43];
        let v255: f64 = v115 * v185;
        let v256: f64 = v118 * v175;
        let v257: f64 = v255 + v256;
        let v258: f64 = v123 * v242;
        let v259: f64 = v240 * v149;
        let v260: f64 = v149 * v259;
        let v261: f64 = v258 + v260;
        let v262: f64 = v257 - v261;
        let v263: f64 = v195 * v262;
        let v264: f64 = v134 * v259;
        let v265: f64 = v240 * v136;
        let v266: f64 = v264 - v265;
        let v267: f64 = v266 - v168;
        let v268: f64 = v192 * v267;
        let v269: f64 = v263 + v268;
        let v270: f64 = v246 * v203;
        let v271: f64 = v226 * v249;
        let v272: f64 = v270 + v271;
        let v273: f64 = v269 + v272;
        let v274: f64 = v254 * v273;
        let v275: f64 = v253 + v274;
        let v276: f64 = v238 + v275;
        let v277: f64 = q[5];
        let (v281, v278): (f64, f64) = ::armdyn_runtime::libm::sincos(v277);
        let v279: f64 = params[54];
        let v280: f64 = v278 * v203;
        let v282: f64 = v281 * v218;
        let v283: f64 = v280 + v282;
        let v284: f64 = v278 * v226;
        let v285: f64 = v281 * v211;
        let v286: f64 = v284 - v285;
        let v287: f64 = qd[5];
        let v288: f64 = v286 * v287;
        let v289: f64 = v283 + v288;
        let v290: f64 = v279 * v289;
        let v291: f64 = params[55];
        let v292: f64 = v278 * v218;
        let v293: f64 = v281 * v203;
        let v294: f64 = v292 - v293;
        let v295: f64 = v278 * v211;
        let v296: f64 = v281 * v226;
        let v297: f64 = v295 + v296;
        let v298: f64 = v297 * v287;
        let v299: f64 = v294 - v298;
        let v300: f64 = v291 * v299;
        let v301: f64 = v290 + v300;
        let v302: f64 = params[56];
        let v303: f64 = qdd[5];
        let v304: f64 = v213 + v303;
        let v305: f64 = v302 * v304;
        let v306: f64 = v301 + v305;
        let v307: f64 = v302 * v297;
        let v308: f64 = params[58];
        let v309: f64 = v308 * v286;
        let v310: f64 = v307 + v309;
        let v311: f64 = params[59];
        let v312: f64 = v200 + v287;
        let v313: f64 = v311 * v312;
        let v314: f64 = v310 + v313;
        let v315: f64 = v286 * v314;
        let v316: f64 = v291 * v297;
        let v317: f64 = params[57];
        let v318: f64 = v317 * v286;
        let v319: f64 = v316 + v318;
        let v320: f64 = v308 * v312;
        let v321: f64 = v319 + v320;
        let v322: f64 = v312 * v321;
        let v323: f64 = v315 - v322;
        let v324: f64 = v306 + v323;
        let v325: f64 = params[52];
        let v326: f64 = v325 * v273;
        let v327: f64 = params[53];
        let v328: f64 = v278 * v252;
        let v329: f64 = v192 * v262;
        let v330: f64 = v195 * v267;
        let v331: f64 = v329 - v330;
        let v332: f64 = v226 * v247;
        let v333: f64 = v246 * v213;
        let v334: f64 = v332 - v333;
        let v335: f64 = v331 + v334;
        let v336: f64 = v281 * v335;
        let v337: f64 = v328 - v336;
        let v338: f64 = v327 * v337;
        let v339: f64 = v326 - v338;
        let v340: f64 = v324 + v339;
        let v341: f64 = q[6];
        let (v345, v342): (f64, f64) = ::armdyn_runtime::libm::sincos(v341);
        let v343: f64 = params[64];
        let v344: f64 = v342 * v289;
        let v346: f64 = v345 * v304;
        let v347: f64 = v344 + v346;
        let v348: f64 = v342 * v312;
        let v349: f64 = v345 * v297;
        let v350: f64 = v348 - v349;
        let v351: f64 = qd[6];
        let v352: f64 = v350 * v351;
        let v353: f64 = v347 + v352;
        let v354: f64 = v343 * v353;
        let v355: f64 = params[65];
        (
            v181,
            v187,
            v190,
            v192,
            v193,
            v195,
            v200,
            v203,
            v205,
            v211,
            v213,
            v216,
            v218,
            v222,
            v225,
            v226,
            v228,
            v231,
            v235,
            v239,
            v240,
            v246,
            v252,
            v254,
            v257,
            v273,
            v276,
            v278,
            v279,
            v281,
            v286,
            v289,
            v291,
            v297,
            v299,
            v302,
            v304,
            v308,
            v311,
            v312,
            v314,
            v317,
            v321,
            v325,
            v327,
            v335,
            v337,
            v340,
            v342,
            v343,
            v345,
            v350,
            v351,
            v353,
            v354,
            v355,
        )
    };
    let (
        v361,
        v363,
        v389,
        v390,
        v395,
        v406,
        v415,
        v435,
        v438,
        v441,
        v452,
        v458,
        v474,
        v476,
        v487,
        v491,
        v499,
        v504,
        v506,
        v508,
        v511,
        v512,
        v518,
        v522,
        v526,
        v528,
        v529,
        v530,
        v533,
    ) = {
        let v356: f64 = v342 * v304;
        let v357: f64 = v345 * v289;
        let v358: f64 = v356 - v357;
        let v359: f64 = v342 * v297;
        let v360: f64 = v345 * v312;
        let v361: f64 = v359 + v360;
        let v362: f64 = v361 * v351;
        let v363: f64 = v358 - v362;
        let v364: f64 = v355 * v363;
        let v365: f64 = v354 + v364;
        let v366: f64 = params[66];
        let v367: f64 = qdd[6];
        let v368: f64 = v367 - v299;
        let v369: f64 = v366 * v368;
        let v370: f64 = v365 + v369;
        let v371: f64 = v366 * v361;
        let v372: f64 = params[68];
        let v373: f64 = v372 * v350;
        let v374: f64 = v371 + v373;
        let v375: f64 = params[69];
        let v376: f64 = v351 - v286;
        let v377: f64 = v375 * v376;
        let v378: f64 = v374 + v377;
        let v379: f64 = v350 * v378;
        let v380: f64 = v355 * v361;
        let v381: f64 = params[67];
        let v382: f64 = v381 * v350;
        let v383: f64 = v380 + v382;
        let v384: f64 = v372 * v376;
        let v385: f64 = v383 + v384;
        let v386: f64 = v376 * v385;
        let v387: f64 = v379 - v386;
        let v388: f64 = v370 + v387;
        let v389: f64 = params[62];
        let v390: f64 = 0.088_f64;
        let v391: f64 = v390 * v304;
        let v392: f64 = v390 * v286;
        let v393: f64 = v297 * v392;
        let v394: f64 = v391 + v393;
        let v395: f64 = v337 + v394;
        let v396: f64 = v389 * v395;
        let v397: f64 = params[63];
        let v398: f64 = v390 * v312;
        let v399: f64 = v297 * v398;
        let v400: f64 = v390 * v299;
        let v401: f64 = v399 - v400;
        let v402: f64 = v273 + v401;
        let v403: f64 = v342 * v402;
        let v404: f64 = v278 * v335;
        let v405: f64 = v281 * v252;
        let v406: f64 = v404 + v405;
        let v407: f64 = v286 * v392;
        let v408: f64 = v312 * v398;
        let v409: f64 = v407 + v408;
        let v410: f64 = v406 - v409;
        let v411: f64 = v345 * v410;
        let v412: f64 = v403 - v411;
        let v413: f64 = v397 * v412;
        let v414: f64 = v396 + v413;
        let v415: f64 = v388 - v414;
        let v416: f64 = v342 * v415;
        let v417: f64 = v355 * v353;
        let v418: f64 = v381 * v363;
        let v419: f64 = v417 + v418;
        let v420: f64 = v372 * v368;
        let v421: f64 = v419 + v420;
        let v422: f64 = v343 * v361;
        let v423: f64 = v355 * v350;
        let v424: f64 = v422 + v423;
        let v425: f64 = v366 * v376;
        let v426: f64 = v424 + v425;
        let v427: f64 = v376 * v426;
        let v428: f64 = v361 * v378;
        let v429: f64 = v427 - v428;
        let v430: f64 = v421 + v429;
        let v431: f64 = v342 * v410;
        let v432: f64 = v345 * v402;
        let v433: f64 = v431 + v432;
        let v434: f64 = v397 * v433;
        let v435: f64 = params[61];
        let v436: f64 = v435 * v395;
        let v437: f64 = v434 + v436;
        let v438: f64 = v430 + v437;
        let v439: f64 = v345 * v438;
        let v440: f64 = v416 - v439;
        let v441: f64 = v340 + v440;
        let v442: f64 = v278 * v441;
        let v443: f64 = v291 * v289;
        let v444: f64 = v317 * v299;
        let v445: f64 = v443 + v444;
        let v446: f64 = v308 * v304;
        let v447: f64 = v445 + v446;
        let v448: f64 = v279 * v297;
        let v449: f64 = v291 * v286;
        let v450: f64 = v448 + v449;
        let v451: f64 = v302 * v312;
        let v452: f64 = v450 + v451;
        let v453: f64 = v312 * v452;
        let v454: f64 = v297 * v314;
        let v455: f64 = v453 - v454;
        let v456: f64 = v447 + v455;
        let v457: f64 = v327 * v406;
        let v458: f64 = params[51];
        let v459: f64 = v458 * v273;
        let v460: f64 = v457 - v459;
        let v461: f64 = v456 + v460;
        let v462: f64 = v366 * v353;
        let v463: f64 = v372 * v363;
        let v464: f64 = v462 + v463;
        let v465: f64 = v375 * v368;
        let v466: f64 = v464 + v465;
        let v467: f64 = v361 * v385;
        let v468: f64 = v350 * v426;
        let v469: f64 = v467 - v468;
        let v470: f64 = v466 + v469;
        let v471: f64 = v435 * v412;
        let v472: f64 = v389 * v433;
        let v473: f64 = v471 - v472;
        let v474: f64 = v470 + v473;
        let v475: f64 = v461 - v474;
        let v476: f64 = params[60];
        let v477: f64 = v476 * v433;
        let v478: f64 = v363 * v397;
        let v479: f64 = v368 * v389;
        let v480: f64 = v478 - v479;
        let v481: f64 = v361 * v389;
        let v482: f64 = v350 * v435;
        let v483: f64 = v481 - v482;
        let v484: f64 = v350 * v483;
        let v485: f64 = v376 * v435;
        let v486: f64 = v361 * v397;
        let v487: f64 = v485 - v486;
        let v488: f64 = v376 * v487;
        let v489: f64 = v484 - v488;
        let v490: f64 = v480 + v489;
        let v491: f64 = v477 + v490;
        let v492: f64 = v345 * v491;
        let v493: f64 = v476 * v412;
        let v494: f64 = v368 * v435;
        let v495: f64 = v353 * v397;
        let v496: f64 = v494 - v495;
        let v497: f64 = v350 * v397;
        let v498: f64 = v376 * v389;
        let v499: f64 = v497 - v498;
        let v500: f64 = v376 * v499;
        let v501: f64 = v361 * v483;
        let v502: f64 = v500 - v501;
        let v503: f64 = v496 + v502;
        let v504: f64 = v493 + v503;
        let v505: f64 = v342 * v504;
        let v506: f64 = v492 + v505;
        let v507: f64 = v390 * v506;
        let v508: f64 = v475 - v507;
        let v509: f64 = v281 * v508;
        let v510: f64 = v442 - v509;
        let v511: f64 = v276 + v510;
        let v512: f64 = params[41];
        let v513: f64 = v218 * v512;
        let v514: f64 = v203 * v254;
        let v515: f64 = v513 - v514;
        let v516: f64 = v200 * v254;
        let v517: f64 = v226 * v239;
        let v518: f64 = v516 + v517;
        let v519: f64 = v226 * v518;
        let v520: f64 = v211 * v239;
        let v521: f64 = v200 * v512;
        let v522: f64 = v520 + v521;
        let v523: f64 = v211 * v522;
        let v524: f64 = v519 + v523;
        let v525: f64 = v515 - v524;
        let v526: f64 = params[40];
        let v527: f64 = v526 * v273;
        let v528: f64 = v525 - v527;
        let v529: f64 = params[50];
        let v530: f64 = v529 * v273;
        let v531: f64 = v289 * v325;
        let v532: f64 = v299 * v458;
        let v533: f64 = v531 - v532;
        (
            v361,
            v363,
            v389,
            v390,
            v395,
            v406,
            v415,
            v435,
            v438,
            v441,
            v452,
            v458,
            v474,
            v476,
            v487,
            v491,
            v499,
            v504,
            v506,
            v508,
            v511,
            v512,
            v518,
            v522,
            v526,
            v528,
            v529,
            v530,
            v533,
        )
    };
    let (
        v546,
        v548,
        v595,
        v604,
        v624,
        v635,
        v638,
        v640,
        v643,
        v654,
        v660,
        v680,
        v684,
        v686,
        v689,
        v690,
        v692,
        v702,
        v706,
        v709,
        v710,
        v711,
    ) = {
        let v534: f64 = v312 * v458;
        let v535: f64 = v297 * v327;
        let v536: f64 = v534 - v535;
        let v537: f64 = v297 * v536;
        let v538: f64 = v286 * v327;
        let v539: f64 = v312 * v325;
        let v540: f64 = v538 - v539;
        let v541: f64 = v286 * v540;
        let v542: f64 = v537 - v541;
        let v543: f64 = v533 + v542;
        let v544: f64 = v530 + v543;
        let v545: f64 = v544 + v506;
        let v546: f64 = v528 - v545;
        let v547: f64 = v246 * v546;
        let v548: f64 = v511 - v547;
        let v549: f64 = v192 * v548;
        let v550: f64 = v205 * v203;
        let v551: f64 = v231 * v213;
        let v552: f64 = v550 - v551;
        let v553: f64 = v222 * v218;
        let v554: f64 = v552 + v553;
        let v555: f64 = v193 * v211;
        let v556: f64 = v205 * v200;
        let v557: f64 = v555 - v556;
        let v558: f64 = v216 * v226;
        let v559: f64 = v557 + v558;
        let v560: f64 = v226 * v559;
        let v561: f64 = v211 * v228;
        let v562: f64 = v560 - v561;
        let v563: f64 = v554 + v562;
        let v564: f64 = v254 * v335;
        let v565: f64 = v512 * v252;
        let v566: f64 = v564 - v565;
        let v567: f64 = v563 + v566;
        let v568: f64 = v302 * v289;
        let v569: f64 = v308 * v299;
        let v570: f64 = v568 + v569;
        let v571: f64 = v311 * v304;
        let v572: f64 = v570 + v571;
        let v573: f64 = v297 * v321;
        let v574: f64 = v286 * v452;
        let v575: f64 = v573 - v574;
        let v576: f64 = v572 + v575;
        let v577: f64 = v458 * v337;
        let v578: f64 = v325 * v406;
        let v579: f64 = v577 - v578;
        let v580: f64 = v576 + v579;
        let v581: f64 = v345 * v415;
        let v582: f64 = v342 * v438;
        let v583: f64 = v581 + v582;
        let v584: f64 = v580 + v583;
        let v585: f64 = v353 * v389;
        let v586: f64 = v363 * v435;
        let v587: f64 = v585 - v586;
        let v588: f64 = v361 * v487;
        let v589: f64 = v350 * v499;
        let v590: f64 = v588 - v589;
        let v591: f64 = v587 + v590;
        let v592: f64 = v476 * v395;
        let v593: f64 = v591 - v592;
        let v594: f64 = v390 * v593;
        let v595: f64 = v584 - v594;
        let v596: f64 = v567 - v595;
        let v597: f64 = v526 * v335;
        let v598: f64 = v213 * v254;
        let v599: f64 = v218 * v239;
        let v600: f64 = v598 + v599;
        let v601: f64 = v200 * v522;
        let v602: f64 = v226 * v512;
        let v603: f64 = v211 * v254;
        let v604: f64 = v602 - v603;
        let v605: f64 = v226 * v604;
        let v606: f64 = v601 + v605;
        let v607: f64 = v600 + v606;
        let v608: f64 = v597 - v607;
        let v609: f64 = v529 * v406;
        let v610: f64 = v299 * v327;
        let v611: f64 = v304 * v325;
        let v612: f64 = v610 - v611;
        let v613: f64 = v297 * v325;
        let v614: f64 = v286 * v458;
        let v615: f64 = v613 - v614;
        let v616: f64 = v286 * v615;
        let v617: f64 = v312 * v536;
        let v618: f64 = v616 - v617;
        let v619: f64 = v612 + v618;
        let v620: f64 = v609 + v619;
        let v621: f64 = v342 * v491;
        let v622: f64 = v345 * v504;
        let v623: f64 = v621 - v622;
        let v624: f64 = v620 + v623;
        let v625: f64 = v278 * v624;
        let v626: f64 = v529 * v337;
        let v627: f64 = v304 * v458;
        let v628: f64 = v289 * v327;
        let v629: f64 = v627 - v628;
        let v630: f64 = v312 * v540;
        let v631: f64 = v297 * v615;
        let v632: f64 = v630 - v631;
        let v633: f64 = v629 + v632;
        let v634: f64 = v626 + v633;
        let v635: f64 = v634 - v593;
        let v636: f64 = v281 * v635;
        let v637: f64 = v625 - v636;
        let v638: f64 = v608 + v637;
        let v639: f64 = v246 * v638;
        let v640: f64 = v596 + v639;
        let v641: f64 = v195 * v640;
        let v642: f64 = v549 - v641;
        let v643: f64 = v190 + v642;
        let v644: f64 = v115 * v643;
        let v645: f64 = v128 * v126;
        let v646: f64 = v154 * v136;
        let v647: f64 = v645 + v646;
        let v648: f64 = v145 * v141;
        let v649: f64 = v647 + v648;
        let v650: f64 = v116 * v134;
        let v651: f64 = v128 * v123;
        let v652: f64 = v650 + v651;
        let v653: f64 = v139 * v149;
        let v654: f64 = v652 + v653;
        let v655: f64 = v149 * v654;
        let v656: f64 = v134 * v151;
        let v657: f64 = v655 - v656;
        let v658: f64 = v649 + v657;
        let v659: f64 = v170 * v257;
        let v660: f64 = params[31];
        let v661: f64 = v660 * v168;
        let v662: f64 = v659 + v661;
        let v663: f64 = v658 + v662;
        let v664: f64 = v216 * v203;
        let v665: f64 = v222 * v213;
        let v666: f64 = v664 - v665;
        let v667: f64 = v225 * v218;
        let v668: f64 = v666 + v667;
        let v669: f64 = v211 * v235;
        let v670: f64 = v200 * v559;
        let v671: f64 = v669 + v670;
        let v672: f64 = v668 + v671;
        let v673: f64 = v512 * v273;
        let v674: f64 = v239 * v335;
        let v675: f64 = v673 + v674;
        let v676: f64 = v672 - v675;
        let v677: f64 = v281 * v441;
        let v678: f64 = v278 * v508;
        let v679: f64 = v677 + v678;
        let v680: f64 = v676 + v679;
        let v681: f64 = v663 + v680;
        let v682: f64 = v195 * v638;
        let v683: f64 = v192 * v546;
        let v684: f64 = v682 + v683;
        let v685: f64 = v240 * v684;
        let v686: f64 = v681 + v685;
        let v687: f64 = v118 * v686;
        let v688: f64 = v644 - v687;
        let v689: f64 = v113 + v688;
        let v690: f64 = params[20];
        let v691: f64 = v690 * v110;
        let v692: f64 = params[21];
        let v693: f64 = v74 * v692;
        let v694: f64 = v59 * v104;
        let v695: f64 = v693 - v694;
        let v696: f64 = v56 * v104;
        let v697: f64 = v82 * v95;
        let v698: f64 = v696 - v697;
        let v699: f64 = v82 * v698;
        let v700: f64 = v67 * v95;
        let v701: f64 = v56 * v692;
        let v702: f64 = v700 - v701;
        let v703: f64 = v67 * v702;
        let v704: f64 = v699 - v703;
        let v705: f64 = v695 + v704;
        let v706: f64 = v691 + v705;
        let v707: f64 = v126 * v162;
        let v708: f64 = v136 * v660;
        let v709: f64 = v707 - v708;
        let v710: f64 = v149 * v660;
        let v711: f64 = v134 * v170;
        (
            v546,
            v548,
            v595,
            v604,
            v624,
            v635,
            v638,
            v640,
            v643,
            v654,
            v660,
            v680,
            v684,
            v686,
            v689,
            v690,
            v692,
            v702,
            v706,
            v709,
            v710,
            v711,
        )
    };
    let (v777, v866, v870, v889) = {
        let v712: f64 = v710 - v711;
        let v713: f64 = v134 * v712;
        let v714: f64 = v123 * v170;
        let v715: f64 = v149 * v162;
        let v716: f64 = v714 - v715;
        let v717: f64 = v123 * v716;
        let v718: f64 = v713 - v717;
        let v719: f64 = v709 + v718;
        let v720: f64 = params[30];
        let v721: f64 = v720 * v168;
        let v722: f64 = v719 - v721;
        let v723: f64 = v722 - v684;
        let v724: f64 = v706 - v723;
        let v725: f64 = v96 * v724;
        let v726: f64 = v689 - v725;
        let v727: f64 = v48 * v726;
        let v728: f64 = v61 * v59;
        let v729: f64 = v87 * v69;
        let v730: f64 = v728 + v729;
        let v731: f64 = v78 * v74;
        let v732: f64 = v730 + v731;
        let v733: f64 = v49 * v67;
        let v734: f64 = v61 * v56;
        let v735: f64 = v733 + v734;
        let v736: f64 = v72 * v82;
        let v737: f64 = v735 + v736;
        let v738: f64 = v82 * v737;
        let v739: f64 = v67 * v84;
        let v740: f64 = v738 - v739;
        let v741: f64 = v732 + v740;
        let v742: f64 = v104 * v181;
        let v743: f64 = v692 * v102;
        let v744: f64 = v742 - v743;
        let v745: f64 = v741 + v744;
        let v746: f64 = v139 * v126;
        let v747: f64 = v145 * v136;
        let v748: f64 = v746 + v747;
        let v749: f64 = v148 * v141;
        let v750: f64 = v748 + v749;
        let v751: f64 = v134 * v158;
        let v752: f64 = v123 * v654;
        let v753: f64 = v751 - v752;
        let v754: f64 = v750 + v753;
        let v755: f64 = v660 * v187;
        let v756: f64 = v162 * v257;
        let v757: f64 = v755 - v756;
        let v758: f64 = v754 + v757;
        let v759: f64 = v195 * v548;
        let v760: f64 = v192 * v640;
        let v761: f64 = v759 + v760;
        let v762: f64 = v758 - v761;
        let v763: f64 = v526 * v252;
        let v764: f64 = v203 * v239;
        let v765: f64 = v213 * v512;
        let v766: f64 = v764 + v765;
        let v767: f64 = v211 * v604;
        let v768: f64 = v200 * v518;
        let v769: f64 = v767 - v768;
        let v770: f64 = v766 + v769;
        let v771: f64 = v763 + v770;
        let v772: f64 = v281 * v624;
        let v773: f64 = v278 * v635;
        let v774: f64 = v772 + v773;
        let v775: f64 = v771 + v774;
        let v776: f64 = v240 * v775;
        let v777: f64 = v762 + v776;
        let v778: f64 = v745 - v777;
        let v779: f64 = v720 * v257;
        let v780: f64 = v136 * v170;
        let v781: f64 = v141 * v162;
        let v782: f64 = v780 - v781;
        let v783: f64 = v134 * v162;
        let v784: f64 = v123 * v660;
        let v785: f64 = v783 - v784;
        let v786: f64 = v123 * v785;
        let v787: f64 = v149 * v712;
        let v788: f64 = v786 - v787;
        let v789: f64 = v782 + v788;
        let v790: f64 = v779 + v789;
        let v791: f64 = v192 * v638;
        let v792: f64 = v195 * v546;
        let v793: f64 = v791 - v792;
        let v794: f64 = v790 + v793;
        let v795: f64 = v118 * v794;
        let v796: f64 = v720 * v187;
        let v797: f64 = v141 * v660;
        let v798: f64 = v126 * v170;
        let v799: f64 = v797 - v798;
        let v800: f64 = v149 * v716;
        let v801: f64 = v134 * v785;
        let v802: f64 = v800 - v801;
        let v803: f64 = v799 + v802;
        let v804: f64 = v796 + v803;
        let v805: f64 = v804 + v775;
        let v806: f64 = v115 * v805;
        let v807: f64 = v795 + v806;
        let v808: f64 = v163 * v807;
        let v809: f64 = v778 - v808;
        let v810: f64 = v690 * v181;
        let v811: f64 = v69 * v104;
        let v812: f64 = v74 * v95;
        let v813: f64 = v811 - v812;
        let v814: f64 = v56 * v702;
        let v815: f64 = v82 * v692;
        let v816: f64 = v67 * v104;
        let v817: f64 = v815 - v816;
        let v818: f64 = v82 * v817;
        let v819: f64 = v814 - v818;
        let v820: f64 = v813 + v819;
        let v821: f64 = v810 + v820;
        let v822: f64 = v115 * v794;
        let v823: f64 = v118 * v805;
        let v824: f64 = v822 - v823;
        let v825: f64 = v821 + v824;
        let v826: f64 = v96 * v825;
        let v827: f64 = v809 + v826;
        let v828: f64 = v50 * v827;
        let v829: f64 = v727 - v828;
        let v830: f64 = v46 + v829;
        let v831: f64 = v4 * v830;
        let v832: f64 = v35 * v12;
        let v833: f64 = v5 * v18;
        let v834: f64 = v832 - v833;
        let v835: f64 = v28 * v22;
        let v836: f64 = v834 + v835;
        let v837: f64 = v21 * v8;
        let v838: f64 = v14 * v7;
        let v839: f64 = v5 * v16;
        let v840: f64 = v838 + v839;
        let v841: f64 = v837 - v840;
        let v842: f64 = v8 * v841;
        let v843: f64 = v7 * v31;
        let v844: f64 = v842 + v843;
        let v845: f64 = v836 + v844;
        let v846: f64 = v42 * v105;
        let v847: f64 = v845 - v846;
        let v848: f64 = v72 * v59;
        let v849: f64 = v78 * v69;
        let v850: f64 = v848 + v849;
        let v851: f64 = v81 * v74;
        let v852: f64 = v850 + v851;
        let v853: f64 = v67 * v91;
        let v854: f64 = v56 * v737;
        let v855: f64 = v853 - v854;
        let v856: f64 = v852 + v855;
        let v857: f64 = v692 * v110;
        let v858: f64 = v95 * v181;
        let v859: f64 = v857 - v858;
        let v860: f64 = v856 + v859;
        let v861: f64 = v118 * v643;
        let v862: f64 = v115 * v686;
        let v863: f64 = v861 + v862;
        let v864: f64 = v860 + v863;
        let v865: f64 = v163 * v723;
        let v866: f64 = v864 - v865;
        let v867: f64 = v847 - v866;
        let v868: f64 = v10 * v867;
        let v869: f64 = v831 + v868;
        let v870: f64 = v2 - v869;
        let v871: f64 = v28 * v12;
        let v872: f64 = v21 * v18;
        let v873: f64 = v871 - v872;
        let v874: f64 = v25 * v22;
        let v875: f64 = v873 + v874;
        let v876: f64 = v16 * v841;
        let v877: f64 = v7 * v38;
        let v878: f64 = v876 - v877;
        let v879: f64 = v875 + v878;
        let v880: f64 = params[12];
        let v881: f64 = v880 * v105;
        let v882: f64 = params[11];
        let v883: f64 = v882 * v44;
        let v884: f64 = v881 - v883;
        let v885: f64 = v879 + v884;
        let v886: f64 = v50 * v726;
        let v887: f64 = v48 * v827;
        let v888: f64 = v886 + v887;
        let v889: f64 = v885 + v888;
        (v777, v866, v870, v889)
    };
    [v870, v889, v866, v777, v680, v595, v474]
}
/// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g. The pivots `D_k` of the factorisation depend on `params`, which must therefore give a positive definite mass matrix (any physical parameter set does: positive masses, inertias that satisfy the triangle inequalities); nothing is checked, and parameters that make a pivot zero give a non-finite result.
///
/// # Inputs
///
/// - `q: &[f64; 7]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 7]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 7]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
/// - `params: &[f64; 70]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `qdd: [f64; 7]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// Operation count: 1545 floating-point operations, 12 trig calls.
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
    q: &[f64; 7],
    qd: &[f64; 7],
    tau: &[f64; 7],
    params: &[f64; 70],
) -> [f64; 7] {
    let (
        v0,
        v2,
        v3,
        v5,
        v6,
        v7,
        v9,
        v10,
        v11,
        v12,
        v15,
        v17,
        v19,
        v22,
        v26,
        v29,
        v33,
        v35,
        v37,
        v39,
        v40,
        v41,
        v44,
        v48,
        v50,
        v54,
        v56,
        v59,
        v63,
        v66,
        v67,
        v69,
        v72,
        v76,
        v80,
        v81,
        v87,
        v89,
        v90,
        v95,
        v98,
        v100,
        v101,
        v103,
        v108,
        v111,
        v113,
        v119,
        v121,
        v124,
        v128,
        v131,
        v132,
        v134,
        v137,
        v141,
        v145,
        v146,
        v151,
        v153,
        v158,
        v164,
        v168,
        v170,
        v173,
        v175,
        v176,
        v178,
        v180,
        v183,
    ) = {
        let v0: f64 = tau[0];
        let v1: f64 = q[1];
        let (v2, v10): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = params[15];
        let v4: f64 = qd[0];
        let v5: f64 = v2 * v4;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = v3 * v7;
        let v9: f64 = params[14];
        let v11: f64 = v10 * v4;
        let v12: f64 = v11 * v6;
        let v13: f64 = v9 * v12;
        let v14: f64 = v8 - v13;
        let v15: f64 = params[19];
        let v16: f64 = v15 * v6;
        let v17: f64 = params[16];
        let v18: f64 = v17 * v5;
        let v19: f64 = params[18];
        let v20: f64 = v19 * v11;
        let v21: f64 = v18 + v20;
        let v22: f64 = v16 - v21;
        let v23: f64 = v11 * v22;
        let v24: f64 = v19 * v6;
        let v25: f64 = v3 * v5;
        let v26: f64 = params[17];
        let v27: f64 = v26 * v11;
        let v28: f64 = v25 + v27;
        let v29: f64 = v24 - v28;
        let v30: f64 = v6 * v29;
        let v31: f64 = v23 + v30;
        let v32: f64 = v14 - v31;
        let v33: f64 = params[13];
        let v34: f64 = 9.81_f64;
        let v35: f64 = v34 * v10;
        let v36: f64 = v33 * v35;
        let v37: f64 = v32 + v36;
        let v38: f64 = q[2];
        let (v41, v39): (f64, f64) = ::armdyn_runtime::libm::sincos(v38);
        let v40: f64 = params[24];
        let v42: f64 = v41 * v5;
        let v43: f64 = v39 * v6;
        let v44: f64 = v42 + v43;
        let v45: f64 = qd[2];
        let v46: f64 = v44 * v45;
        let v47: f64 = v39 * v12;
        let v48: f64 = v46 - v47;
        let v49: f64 = v40 * v48;
        let v50: f64 = params[25];
        let v51: f64 = v41 * v12;
        let v52: f64 = v41 * v6;
        let v53: f64 = v39 * v5;
        let v54: f64 = v52 - v53;
        let v55: f64 = v54 * v45;
        let v56: f64 = v51 - v55;
        let v57: f64 = v50 * v56;
        let v58: f64 = v49 + v57;
        let v59: f64 = params[26];
        let v60: f64 = v59 * v7;
        let v61: f64 = v58 - v60;
        let v62: f64 = v59 * v54;
        let v63: f64 = params[28];
        let v64: f64 = v63 * v44;
        let v65: f64 = v62 + v64;
        let v66: f64 = params[29];
        let v67: f64 = v11 + v45;
        let v68: f64 = v66 * v67;
        let v69: f64 = v65 + v68;
        let v70: f64 = v44 * v69;
        let v71: f64 = v50 * v54;
        let v72: f64 = params[27];
        let v73: f64 = v72 * v44;
        let v74: f64 = v71 + v73;
        let v75: f64 = v63 * v67;
        let v76: f64 = v74 + v75;
        let v77: f64 = v67 * v76;
        let v78: f64 = v70 - v77;
        let v79: f64 = v61 + v78;
        let v80: f64 = params[22];
        let v81: f64 = 0.316_f64;
        let v82: f64 = v81 * v54;
        let v83: f64 = v54 * v82;
        let v84: f64 = v81 * v44;
        let v85: f64 = v44 * v84;
        let v86: f64 = v83 + v85;
        let v87: f64 = v35 - v86;
        let v88: f64 = v80 * v87;
        let v89: f64 = params[23];
        let v90: f64 = v34 * v2;
        let v91: f64 = v41 * v90;
        let v92: f64 = v67 * v84;
        let v93: f64 = v81 * v48;
        let v94: f64 = v92 - v93;
        let v95: f64 = v91 + v94;
        let v96: f64 = v89 * v95;
        let v97: f64 = v88 - v96;
        let v98: f64 = v79 + v97;
        let v99: f64 = q[3];
        let (v103, v100): (f64, f64) = ::armdyn_runtime::libm::sincos(v99);
        let v101: f64 = params[34];
        let v102: f64 = v100 * v48;
        let v104: f64 = v103 * v7;
        let v105: f64 = v102 - v104;
        let v106: f64 = v100 * v67;
        let v107: f64 = v103 * v54;
        let v108: f64 = v106 - v107;
        let v109: f64 = qd[3];
        let v110: f64 = v108 * v109;
        let v111: f64 = v105 + v110;
        let v112: f64 = v101 * v111;
        let v113: f64 = params[35];
        let v114: f64 = v103 * v48;
        let v115: f64 = v100 * v7;
        let v116: f64 = v114 + v115;
        let v117: f64 = v100 * v54;
        let v118: f64 = v103 * v67;
        let v119: f64 = v117 + v118;
        let v120: f64 = v119 * v109;
        let v121: f64 = v116 + v120;
        let v122: f64 = v113 * v121;
        let v123: f64 = v112 - v122;
        let v124: f64 = params[36];
        let v125: f64 = v124 * v56;
        let v126: f64 = v123 - v125;
        let v127: f64 = v124 * v119;
        let v128: f64 = params[38];
        let v129: f64 = v128 * v108;
        let v130: f64 = v127 + v129;
        let v131: f64 = params[39];
        let v132: f64 = v109 - v44;
        let v133: f64 = v131 * v132;
        let v134: f64 = v130 + v133;
        let v135: f64 = v108 * v134;
        let v136: f64 = v113 * v119;
        let v137: f64 = params[37];
        let v138: f64 = v137 * v108;
        let v139: f64 = v136 + v138;
        let v140: f64 = v128 * v132;
        let v141: f64 = v139 + v140;
        let v142: f64 = v132 * v141;
        let v143: f64 = v135 - v142;
        let v144: f64 = v126 + v143;
        let v145: f64 = params[32];
        let v146: f64 = 0.0825_f64;
        let v147: f64 = v146 * v44;
        let v148: f64 = v54 * v147;
        let v149: f64 = v146 * v7;
        let v150: f64 = v148 - v149;
        let v151: f64 = v95 + v150;
        let v152: f64 = v145 * v151;
        let v153: f64 = params[33];
        let v154: f64 = v146 * v67;
        let v155: f64 = v54 * v154;
        let v156: f64 = v146 * v56;
        let v157: f64 = v155 - v156;
        let v158: f64 = v87 + v157;
        let v159: f64 = v100 * v158;
        let v160: f64 = v81 * v56;
        let v161: f64 = v67 * v82;
        let v162: f64 = v160 + v161;
        let v163: f64 = v39 * v90;
        let v164: f64 = v162 - v163;
        let v165: f64 = v44 * v147;
        let v166: f64 = v67 * v154;
        let v167: f64 = v165 + v166;
        let v168: f64 = v164 - v167;
        let v169: f64 = v103 * v168;
        let v170: f64 = v159 - v169;
        let v171: f64 = v153 * v170;
        let v172: f64 = v152 + v171;
        let v173: f64 = v144 - v172;
        let v174: f64 = q[4];
        let (v178, v175): (f64, f64) = ::armdyn_runtime::libm::sincos(v174);
        let v176: f64 = params[44];
        let v177: f64 = v175 * v111;
        let v179: f64 = v178 * v56;
        let v180: f64 = v177 + v179;
        let v181: f64 = v178 * v119;
        let v182: f64 = v175 * v132;
        let v183: f64 = v181 + v182;
        (
            v0,
            v2,
            v3,
            v5,
            v6,
            v7,
            v9,
            v10,
            v11,
            v12,
            v15,
            v17,
            v19,
            v22,
            v26,
            v29,
            v33,
            v35,
            v37,
            v39,
            v40,
            v41,
            v44,
            v48,
            v50,
            v54,
            v56,
            v59,
            v63,
            v66,
            v67,
            v69,
            v72,
            v76,
            v80,
            v81,
            v87,
            v89,
            v90,
            v95,
            v98,
            v100,
            v101,
            v103,
            v108,
            v111,
            v113,
            v119,
            v121,
            v124,
            v128,
            v131,
            v132,
            v134,
            v137,
            v141,
            v145,
            v146,
            v151,
            v153,
            v158,
            v164,
            v168,
            v170,
            v173,
            v175,
            v176,
            v178,
            v180,
            v183,
        )
    };
    let (
        v186,
        v188,
        v194,
        v196,
        v199,
        v203,
        v206,
        v207,
        v209,
        v212,
        v216,
        v220,
        v221,
        v227,
        v233,
        v235,
        v238,
        v254,
        v257,
        v259,
        v260,
        v262,
        v267,
        v270,
        v272,
        v278,
        v280,
        v283,
        v287,
        v290,
        v291,
        v293,
        v296,
        v300,
        v304,
        v306,
        v314,
        v316,
        v319,
        v321,
        v322,
        v324,
        v329,
        v332,
        v334,
        v340,
        v342,
        v345,
        v349,
        v352,
        v353,
        v355,
        v358,
        v362,
        v365,
        v366,
        v367,
    ) = {
        let v184: f64 = qd[4];
        let v185: f64 = v183 * v184;
        let v186: f64 = v180 - v185;
        let v187: f64 = v176 * v186;
        let v188: f64 = params[45];
        let v189: f64 = v175 * v56;
        let v190: f64 = v178 * v111;
        let v191: f64 = v189 - v190;
        let v192: f64 = v175 * v119;
        let v193: f64 = v178 * v132;
        let v194: f64 = v192 - v193;
        let v195: f64 = v194 * v184;
        let v196: f64 = v191 - v195;
        let v197: f64 = v188 * v196;
        let v198: f64 = v187 + v197;
        let v199: f64 = params[46];
        let v200: f64 = v199 * v121;
        let v201: f64 = v198 - v200;
        let v202: f64 = v199 * v194;
        let v203: f64 = params[48];
        let v204: f64 = v203 * v183;
        let v205: f64 = v202 - v204;
        let v206: f64 = params[49];
        let v207: f64 = v108 + v184;
        let v208: f64 = v206 * v207;
        let v209: f64 = v205 + v208;
        let v210: f64 = v183 * v209;
        let v211: f64 = v188 * v194;
        let v212: f64 = params[47];
        let v213: f64 = v212 * v183;
        let v214: f64 = v211 - v213;
        let v215: f64 = v203 * v207;
        let v216: f64 = v214 + v215;
        let v217: f64 = v207 * v216;
        let v218: f64 = v210 + v217;
        let v219: f64 = v201 - v218;
        let v220: f64 = params[42];
        let v221: f64 = -0.0825_f64;
        let v222: f64 = v221 * v108;
        let v223: f64 = v119 * v222;
        let v224: f64 = v221 * v56;
        let v225: f64 = v223 - v224;
        let v226: f64 = v170 + v225;
        let v227: f64 = 0.384_f64;
        let v228: f64 = v227 * v194;
        let v229: f64 = v194 * v228;
        let v230: f64 = v227 * v183;
        let v231: f64 = v183 * v230;
        let v232: f64 = v229 + v231;
        let v233: f64 = v226 - v232;
        let v234: f64 = v220 * v233;
        let v235: f64 = params[43];
        let v236: f64 = v100 * v168;
        let v237: f64 = v103 * v158;
        let v238: f64 = v236 + v237;
        let v239: f64 = v108 * v222;
        let v240: f64 = v221 * v132;
        let v241: f64 = v132 * v240;
        let v242: f64 = v239 + v241;
        let v243: f64 = v238 - v242;
        let v244: f64 = v178 * v243;
        let v245: f64 = v221 * v121;
        let v246: f64 = v119 * v240;
        let v247: f64 = v245 + v246;
        let v248: f64 = v247 - v151;
        let v249: f64 = v175 * v248;
        let v250: f64 = v244 + v249;
        let v251: f64 = v227 * v186;
        let v252: f64 = v207 * v230;
        let v253: f64 = v251 + v252;
        let v254: f64 = v250 + v253;
        let v255: f64 = v235 * v254;
        let v256: f64 = v234 + v255;
        let v257: f64 = v219 + v256;
        let v258: f64 = q[5];
        let (v262, v259): (f64, f64) = ::armdyn_runtime::libm::sincos(v258);
        let v260: f64 = params[54];
        let v261: f64 = v259 * v186;
        let v263: f64 = v262 * v121;
        let v264: f64 = v261 - v263;
        let v265: f64 = v259 * v207;
        let v266: f64 = v262 * v194;
        let v267: f64 = v265 - v266;
        let v268: f64 = qd[5];
        let v269: f64 = v267 * v268;
        let v270: f64 = v264 + v269;
        let v271: f64 = v260 * v270;
        let v272: f64 = params[55];
        let v273: f64 = v262 * v186;
        let v274: f64 = v259 * v121;
        let v275: f64 = v273 + v274;
        let v276: f64 = v259 * v194;
        let v277: f64 = v262 * v207;
        let v278: f64 = v276 + v277;
        let v279: f64 = v278 * v268;
        let v280: f64 = v275 + v279;
        let v281: f64 = v272 * v280;
        let v282: f64 = v271 - v281;
        let v283: f64 = params[56];
        let v284: f64 = v283 * v196;
        let v285: f64 = v282 - v284;
        let v286: f64 = v283 * v278;
        let v287: f64 = params[58];
        let v288: f64 = v287 * v267;
        let v289: f64 = v286 + v288;
        let v290: f64 = params[59];
        let v291: f64 = v183 + v268;
        let v292: f64 = v290 * v291;
        let v293: f64 = v289 + v292;
        let v294: f64 = v267 * v293;
        let v295: f64 = v272 * v278;
        let v296: f64 = params[57];
        let v297: f64 = v296 * v267;
        let v298: f64 = v295 + v297;
        let v299: f64 = v287 * v291;
        let v300: f64 = v298 + v299;
        let v301: f64 = v291 * v300;
        let v302: f64 = v294 - v301;
        let v303: f64 = v285 + v302;
        let v304: f64 = params[52];
        let v305: f64 = v304 * v254;
        let v306: f64 = params[53];
        let v307: f64 = v259 * v233;
        let v308: f64 = v175 * v243;
        let v309: f64 = v178 * v248;
        let v310: f64 = v308 - v309;
        let v311: f64 = v227 * v196;
        let v312: f64 = v207 * v228;
        let v313: f64 = v311 + v312;
        let v314: f64 = v310 + v313;
        let v315: f64 = v262 * v314;
        let v316: f64 = v307 - v315;
        let v317: f64 = v306 * v316;
        let v318: f64 = v305 - v317;
        let v319: f64 = v303 + v318;
        let v320: f64 = q[6];
        let (v324, v321): (f64, f64) = ::armdyn_runtime::libm::sincos(v320);
        let v322: f64 = params[64];
        let v323: f64 = v321 * v270;
        let v325: f64 = v324 * v196;
        let v326: f64 = v323 - v325;
        let v327: f64 = v321 * v291;
        let v328: f64 = v324 * v278;
        let v329: f64 = v327 - v328;
        let v330: f64 = qd[6];
        let v331: f64 = v329 * v330;
        let v332: f64 = v326 + v331;
        let v333: f64 = v322 * v332;
        let v334: f64 = params[65];
        let v335: f64 = v324 * v270;
        let v336: f64 = v321 * v196;
        let v337: f64 = v335 + v336;
        let v338: f64 = v321 * v278;
        let v339: f64 = v324 * v291;
        let v340: f64 = v338 + v339;
        let v341: f64 = v340 * v330;
        let v342: f64 = v337 + v341;
        let v343: f64 = v334 * v342;
        let v344: f64 = v333 - v343;
        let v345: f64 = params[66];
        let v346: f64 = v345 * v280;
        let v347: f64 = v344 + v346;
        let v348: f64 = v345 * v340;
        let v349: f64 = params[68];
        let v350: f64 = v349 * v329;
        let v351: f64 = v348 + v350;
        let v352: f64 = params[69];
        let v353: f64 = v330 - v267;
        let v354: f64 = v352 * v353;
        let v355: f64 = v351 + v354;
        let v356: f64 = v329 * v355;
        let v357: f64 = v334 * v340;
        let v358: f64 = params[67];
        let v359: f64 = v358 * v329;
        let v360: f64 = v357 + v359;
        let v361: f64 = v349 * v353;
        let v362: f64 = v360 + v361;
        let v363: f64 = v353 * v362;
        let v364: f64 = v356 - v363;
        let v365: f64 = v347 + v364;
        let v366: f64 = params[62];
        let v367: f64 = 0.088_f64;
        (
            v186,
            v188,
            v194,
            v196,
            v199,
            v203,
            v206,
            v207,
            v209,
            v212,
            v216,
            v220,
            v221,
            v227,
            v233,
            v235,
            v238,
            v254,
            v257,
            v259,
            v260,
            v262,
            v267,
            v270,
            v272,
            v278,
            v280,
            v283,
            v287,
            v290,
            v291,
            v293,
            v296,
            v300,
            v304,
            v306,
            v314,
            v316,
            v319,
            v321,
            v322,
            v324,
            v329,
            v332,
            v334,
            v340,
            v342,
            v345,
            v349,
            v352,
            v353,
            v355,
            v358,
            v362,
            v365,
            v366,
            v367,
        )
    };
    let (
        v372,
        v374,
        v383,
        v392,
        v412,
        v415,
        v418,
        v435,
        v451,
        v453,
        v461,
        v468,
        v476,
        v481,
        v485,
        v489,
        v491,
        v497,
        v501,
        v506,
        v513,
        v517,
        v523,
        v525,
        v526,
        v536,
        v544,
        v549,
        v550,
        v551,
    ) = {
        let v368: f64 = v367 * v267;
        let v369: f64 = v278 * v368;
        let v370: f64 = v367 * v196;
        let v371: f64 = v369 - v370;
        let v372: f64 = v316 + v371;
        let v373: f64 = v366 * v372;
        let v374: f64 = params[63];
        let v375: f64 = v367 * v280;
        let v376: f64 = v367 * v291;
        let v377: f64 = v278 * v376;
        let v378: f64 = v375 + v377;
        let v379: f64 = v254 + v378;
        let v380: f64 = v321 * v379;
        let v381: f64 = v259 * v314;
        let v382: f64 = v262 * v233;
        let v383: f64 = v381 + v382;
        let v384: f64 = v267 * v368;
        let v385: f64 = v291 * v376;
        let v386: f64 = v384 + v385;
        let v387: f64 = v383 - v386;
        let v388: f64 = v324 * v387;
        let v389: f64 = v380 - v388;
        let v390: f64 = v374 * v389;
        let v391: f64 = v373 + v390;
        let v392: f64 = v365 - v391;
        let v393: f64 = v321 * v392;
        let v394: f64 = v334 * v332;
        let v395: f64 = v358 * v342;
        let v396: f64 = v394 - v395;
        let v397: f64 = v349 * v280;
        let v398: f64 = v396 + v397;
        let v399: f64 = v322 * v340;
        let v400: f64 = v334 * v329;
        let v401: f64 = v399 + v400;
        let v402: f64 = v345 * v353;
        let v403: f64 = v401 + v402;
        let v404: f64 = v353 * v403;
        let v405: f64 = v340 * v355;
        let v406: f64 = v404 - v405;
        let v407: f64 = v398 + v406;
        let v408: f64 = v321 * v387;
        let v409: f64 = v324 * v379;
        let v410: f64 = v408 + v409;
        let v411: f64 = v374 * v410;
        let v412: f64 = params[61];
        let v413: f64 = v412 * v372;
        let v414: f64 = v411 + v413;
        let v415: f64 = v407 + v414;
        let v416: f64 = v324 * v415;
        let v417: f64 = v393 - v416;
        let v418: f64 = v319 + v417;
        let v419: f64 = v259 * v418;
        let v420: f64 = v272 * v270;
        let v421: f64 = v296 * v280;
        let v422: f64 = v420 - v421;
        let v423: f64 = v287 * v196;
        let v424: f64 = v422 - v423;
        let v425: f64 = v260 * v278;
        let v426: f64 = v272 * v267;
        let v427: f64 = v425 + v426;
        let v428: f64 = v283 * v291;
        let v429: f64 = v427 + v428;
        let v430: f64 = v291 * v429;
        let v431: f64 = v278 * v293;
        let v432: f64 = v430 - v431;
        let v433: f64 = v424 + v432;
        let v434: f64 = v306 * v383;
        let v435: f64 = params[51];
        let v436: f64 = v435 * v254;
        let v437: f64 = v434 - v436;
        let v438: f64 = v433 + v437;
        let v439: f64 = v345 * v332;
        let v440: f64 = v349 * v342;
        let v441: f64 = v439 - v440;
        let v442: f64 = v352 * v280;
        let v443: f64 = v441 + v442;
        let v444: f64 = v340 * v362;
        let v445: f64 = v329 * v403;
        let v446: f64 = v444 - v445;
        let v447: f64 = v443 + v446;
        let v448: f64 = v412 * v389;
        let v449: f64 = v366 * v410;
        let v450: f64 = v448 - v449;
        let v451: f64 = v447 + v450;
        let v452: f64 = v438 - v451;
        let v453: f64 = params[60];
        let v454: f64 = v453 * v410;
        let v455: f64 = v340 * v366;
        let v456: f64 = v329 * v412;
        let v457: f64 = v455 - v456;
        let v458: f64 = v329 * v457;
        let v459: f64 = v353 * v412;
        let v460: f64 = v340 * v374;
        let v461: f64 = v459 - v460;
        let v462: f64 = v353 * v461;
        let v463: f64 = v458 - v462;
        let v464: f64 = v342 * v374;
        let v465: f64 = v280 * v366;
        let v466: f64 = v464 + v465;
        let v467: f64 = v463 - v466;
        let v468: f64 = v454 + v467;
        let v469: f64 = v324 * v468;
        let v470: f64 = v453 * v389;
        let v471: f64 = v280 * v412;
        let v472: f64 = v332 * v374;
        let v473: f64 = v471 - v472;
        let v474: f64 = v329 * v374;
        let v475: f64 = v353 * v366;
        let v476: f64 = v474 - v475;
        let v477: f64 = v353 * v476;
        let v478: f64 = v340 * v457;
        let v479: f64 = v477 - v478;
        let v480: f64 = v473 + v479;
        let v481: f64 = v470 + v480;
        let v482: f64 = v321 * v481;
        let v483: f64 = v469 + v482;
        let v484: f64 = v367 * v483;
        let v485: f64 = v452 - v484;
        let v486: f64 = v262 * v485;
        let v487: f64 = v419 - v486;
        let v488: f64 = v257 + v487;
        let v489: f64 = params[40];
        let v490: f64 = v489 * v254;
        let v491: f64 = params[41];
        let v492: f64 = v121 * v491;
        let v493: f64 = v186 * v235;
        let v494: f64 = v492 + v493;
        let v495: f64 = v183 * v235;
        let v496: f64 = v207 * v220;
        let v497: f64 = v495 + v496;
        let v498: f64 = v207 * v497;
        let v499: f64 = v194 * v220;
        let v500: f64 = v183 * v491;
        let v501: f64 = v499 + v500;
        let v502: f64 = v194 * v501;
        let v503: f64 = v498 + v502;
        let v504: f64 = v494 + v503;
        let v505: f64 = v490 + v504;
        let v506: f64 = params[50];
        let v507: f64 = v506 * v254;
        let v508: f64 = v270 * v304;
        let v509: f64 = v280 * v435;
        let v510: f64 = v508 + v509;
        let v511: f64 = v291 * v435;
        let v512: f64 = v278 * v306;
        let v513: f64 = v511 - v512;
        let v514: f64 = v278 * v513;
        let v515: f64 = v267 * v306;
        let v516: f64 = v291 * v304;
        let v517: f64 = v515 - v516;
        let v518: f64 = v267 * v517;
        let v519: f64 = v514 - v518;
        let v520: f64 = v510 + v519;
        let v521: f64 = v507 + v520;
        let v522: f64 = v521 + v483;
        let v523: f64 = v505 + v522;
        let v524: f64 = v227 * v523;
        let v525: f64 = v488 + v524;
        let v526: f64 = v175 * v525;
        let v527: f64 = v188 * v186;
        let v528: f64 = v212 * v196;
        let v529: f64 = v527 + v528;
        let v530: f64 = v203 * v121;
        let v531: f64 = v529 - v530;
        let v532: f64 = v176 * v194;
        let v533: f64 = v188 * v183;
        let v534: f64 = v532 - v533;
        let v535: f64 = v199 * v207;
        let v536: f64 = v534 + v535;
        let v537: f64 = v207 * v536;
        let v538: f64 = v194 * v209;
        let v539: f64 = v537 - v538;
        let v540: f64 = v531 + v539;
        let v541: f64 = v235 * v314;
        let v542: f64 = v491 * v233;
        let v543: f64 = v541 - v542;
        let v544: f64 = v540 + v543;
        let v545: f64 = v283 * v270;
        let v546: f64 = v287 * v280;
        let v547: f64 = v545 - v546;
        let v548: f64 = v290 * v196;
        let v549: f64 = v547 - v548;
        let v550: f64 = v278 * v300;
        let v551: f64 = v267 * v429;
        (
            v372,
            v374,
            v383,
            v392,
            v412,
            v415,
            v418,
            v435,
            v451,
            v453,
            v461,
            v468,
            v476,
            v481,
            v485,
            v489,
            v491,
            v497,
            v501,
            v506,
            v513,
            v517,
            v523,
            v525,
            v526,
            v536,
            v544,
            v549,
            v550,
            v551,
        )
    };
    let (
        v572,
        v581,
        v601,
        v612,
        v615,
        v617,
        v620,
        v637,
        v657,
        v663,
        v667,
        v674,
        v676,
        v689,
        v693,
        v697,
        v700,
        v703,
        v704,
        v714,
        v722,
        v735,
    ) = {
        let v552: f64 = v550 - v551;
        let v553: f64 = v549 + v552;
        let v554: f64 = v435 * v316;
        let v555: f64 = v304 * v383;
        let v556: f64 = v554 - v555;
        let v557: f64 = v553 + v556;
        let v558: f64 = v324 * v392;
        let v559: f64 = v321 * v415;
        let v560: f64 = v558 + v559;
        let v561: f64 = v557 + v560;
        let v562: f64 = v332 * v366;
        let v563: f64 = v342 * v412;
        let v564: f64 = v562 + v563;
        let v565: f64 = v340 * v461;
        let v566: f64 = v329 * v476;
        let v567: f64 = v565 - v566;
        let v568: f64 = v564 + v567;
        let v569: f64 = v453 * v372;
        let v570: f64 = v568 - v569;
        let v571: f64 = v367 * v570;
        let v572: f64 = v561 - v571;
        let v573: f64 = v544 - v572;
        let v574: f64 = v489 * v314;
        let v575: f64 = v196 * v235;
        let v576: f64 = v121 * v220;
        let v577: f64 = v575 + v576;
        let v578: f64 = v183 * v501;
        let v579: f64 = v207 * v491;
        let v580: f64 = v194 * v235;
        let v581: f64 = v579 - v580;
        let v582: f64 = v207 * v581;
        let v583: f64 = v578 + v582;
        let v584: f64 = v577 - v583;
        let v585: f64 = v574 + v584;
        let v586: f64 = v506 * v383;
        let v587: f64 = v196 * v304;
        let v588: f64 = v280 * v306;
        let v589: f64 = v587 - v588;
        let v590: f64 = v278 * v304;
        let v591: f64 = v267 * v435;
        let v592: f64 = v590 - v591;
        let v593: f64 = v267 * v592;
        let v594: f64 = v291 * v513;
        let v595: f64 = v593 - v594;
        let v596: f64 = v589 + v595;
        let v597: f64 = v586 + v596;
        let v598: f64 = v321 * v468;
        let v599: f64 = v324 * v481;
        let v600: f64 = v598 - v599;
        let v601: f64 = v597 + v600;
        let v602: f64 = v259 * v601;
        let v603: f64 = v506 * v316;
        let v604: f64 = v291 * v517;
        let v605: f64 = v278 * v592;
        let v606: f64 = v604 - v605;
        let v607: f64 = v196 * v435;
        let v608: f64 = v270 * v306;
        let v609: f64 = v607 + v608;
        let v610: f64 = v606 - v609;
        let v611: f64 = v603 + v610;
        let v612: f64 = v611 - v570;
        let v613: f64 = v262 * v612;
        let v614: f64 = v602 - v613;
        let v615: f64 = v585 + v614;
        let v616: f64 = v227 * v615;
        let v617: f64 = v573 + v616;
        let v618: f64 = v178 * v617;
        let v619: f64 = v526 - v618;
        let v620: f64 = v173 + v619;
        let v621: f64 = v100 * v620;
        let v622: f64 = v113 * v111;
        let v623: f64 = v137 * v121;
        let v624: f64 = v622 - v623;
        let v625: f64 = v128 * v56;
        let v626: f64 = v624 - v625;
        let v627: f64 = v101 * v119;
        let v628: f64 = v113 * v108;
        let v629: f64 = v627 + v628;
        let v630: f64 = v124 * v132;
        let v631: f64 = v629 + v630;
        let v632: f64 = v132 * v631;
        let v633: f64 = v119 * v134;
        let v634: f64 = v632 - v633;
        let v635: f64 = v626 + v634;
        let v636: f64 = v153 * v238;
        let v637: f64 = params[31];
        let v638: f64 = v637 * v151;
        let v639: f64 = v636 + v638;
        let v640: f64 = v635 + v639;
        let v641: f64 = v199 * v186;
        let v642: f64 = v203 * v196;
        let v643: f64 = v641 + v642;
        let v644: f64 = v206 * v121;
        let v645: f64 = v643 - v644;
        let v646: f64 = v194 * v216;
        let v647: f64 = v183 * v536;
        let v648: f64 = v646 + v647;
        let v649: f64 = v645 + v648;
        let v650: f64 = v491 * v254;
        let v651: f64 = v220 * v314;
        let v652: f64 = v650 + v651;
        let v653: f64 = v649 - v652;
        let v654: f64 = v262 * v418;
        let v655: f64 = v259 * v485;
        let v656: f64 = v654 + v655;
        let v657: f64 = v653 + v656;
        let v658: f64 = v640 + v657;
        let v659: f64 = v175 * v523;
        let v660: f64 = v178 * v615;
        let v661: f64 = v659 - v660;
        let v662: f64 = v221 * v661;
        let v663: f64 = v658 - v662;
        let v664: f64 = v103 * v663;
        let v665: f64 = v621 - v664;
        let v666: f64 = v98 + v665;
        let v667: f64 = params[20];
        let v668: f64 = v667 * v95;
        let v669: f64 = v44 * v89;
        let v670: f64 = v67 * v80;
        let v671: f64 = v669 - v670;
        let v672: f64 = v67 * v671;
        let v673: f64 = v54 * v80;
        let v674: f64 = params[21];
        let v675: f64 = v44 * v674;
        let v676: f64 = v673 - v675;
        let v677: f64 = v54 * v676;
        let v678: f64 = v672 - v677;
        let v679: f64 = v7 * v674;
        let v680: f64 = v48 * v89;
        let v681: f64 = v679 + v680;
        let v682: f64 = v678 - v681;
        let v683: f64 = v668 + v682;
        let v684: f64 = v111 * v145;
        let v685: f64 = v121 * v637;
        let v686: f64 = v684 + v685;
        let v687: f64 = v132 * v637;
        let v688: f64 = v119 * v153;
        let v689: f64 = v687 - v688;
        let v690: f64 = v119 * v689;
        let v691: f64 = v108 * v153;
        let v692: f64 = v132 * v145;
        let v693: f64 = v691 - v692;
        let v694: f64 = v108 * v693;
        let v695: f64 = v690 - v694;
        let v696: f64 = v686 + v695;
        let v697: f64 = params[30];
        let v698: f64 = v697 * v151;
        let v699: f64 = v696 - v698;
        let v700: f64 = v699 + v661;
        let v701: f64 = v683 - v700;
        let v702: f64 = v81 * v701;
        let v703: f64 = v666 - v702;
        let v704: f64 = v39 * v703;
        let v705: f64 = v50 * v48;
        let v706: f64 = v72 * v56;
        let v707: f64 = v705 + v706;
        let v708: f64 = v63 * v7;
        let v709: f64 = v707 - v708;
        let v710: f64 = v40 * v54;
        let v711: f64 = v50 * v44;
        let v712: f64 = v710 + v711;
        let v713: f64 = v59 * v67;
        let v714: f64 = v712 + v713;
        let v715: f64 = v67 * v714;
        let v716: f64 = v54 * v69;
        let v717: f64 = v715 - v716;
        let v718: f64 = v709 + v717;
        let v719: f64 = v89 * v164;
        let v720: f64 = v674 * v87;
        let v721: f64 = v719 - v720;
        let v722: f64 = v718 + v721;
        let v723: f64 = v124 * v111;
        let v724: f64 = v128 * v121;
        let v725: f64 = v723 - v724;
        let v726: f64 = v131 * v56;
        let v727: f64 = v725 - v726;
        let v728: f64 = v119 * v141;
        let v729: f64 = v108 * v631;
        let v730: f64 = v728 - v729;
        let v731: f64 = v727 + v730;
        let v732: f64 = v637 * v170;
        let v733: f64 = v145 * v238;
        let v734: f64 = v732 - v733;
        let v735: f64 = v731 + v734;
        (
            v572,
            v581,
            v601,
            v612,
            v615,
            v617,
            v620,
            v637,
            v657,
            v663,
            v667,
            v674,
            v676,
            v689,
            v693,
            v697,
            v700,
            v703,
            v704,
            v714,
            v722,
            v735,
        )
    };
    let (
        v754,
        v804,
        v816,
        v841,
        v845,
        v848,
        v852,
        v853,
        v860,
        v863,
        v864,
        v869,
        v875,
        v881,
        v885,
        v897,
        v902,
        v905,
        v908,
        v915,
        v916,
        v918,
        v919,
    ) = {
        let v736: f64 = v178 * v525;
        let v737: f64 = v175 * v617;
        let v738: f64 = v736 + v737;
        let v739: f64 = v735 - v738;
        let v740: f64 = v489 * v233;
        let v741: f64 = v186 * v220;
        let v742: f64 = v196 * v491;
        let v743: f64 = v741 - v742;
        let v744: f64 = v194 * v581;
        let v745: f64 = v183 * v497;
        let v746: f64 = v744 - v745;
        let v747: f64 = v743 + v746;
        let v748: f64 = v740 + v747;
        let v749: f64 = v262 * v601;
        let v750: f64 = v259 * v612;
        let v751: f64 = v749 + v750;
        let v752: f64 = v748 + v751;
        let v753: f64 = v221 * v752;
        let v754: f64 = v739 + v753;
        let v755: f64 = v722 - v754;
        let v756: f64 = v697 * v238;
        let v757: f64 = v56 * v145;
        let v758: f64 = v121 * v153;
        let v759: f64 = v757 - v758;
        let v760: f64 = v119 * v145;
        let v761: f64 = v108 * v637;
        let v762: f64 = v760 - v761;
        let v763: f64 = v108 * v762;
        let v764: f64 = v132 * v689;
        let v765: f64 = v763 - v764;
        let v766: f64 = v759 + v765;
        let v767: f64 = v756 + v766;
        let v768: f64 = v175 * v615;
        let v769: f64 = v178 * v523;
        let v770: f64 = v768 + v769;
        let v771: f64 = v767 + v770;
        let v772: f64 = v103 * v771;
        let v773: f64 = v697 * v170;
        let v774: f64 = v132 * v693;
        let v775: f64 = v119 * v762;
        let v776: f64 = v774 - v775;
        let v777: f64 = v56 * v637;
        let v778: f64 = v111 * v153;
        let v779: f64 = v777 + v778;
        let v780: f64 = v776 - v779;
        let v781: f64 = v773 + v780;
        let v782: f64 = v781 + v752;
        let v783: f64 = v100 * v782;
        let v784: f64 = v772 + v783;
        let v785: f64 = v146 * v784;
        let v786: f64 = v755 - v785;
        let v787: f64 = v667 * v164;
        let v788: f64 = v56 * v89;
        let v789: f64 = v7 * v80;
        let v790: f64 = v788 + v789;
        let v791: f64 = v44 * v676;
        let v792: f64 = v67 * v674;
        let v793: f64 = v54 * v89;
        let v794: f64 = v792 - v793;
        let v795: f64 = v67 * v794;
        let v796: f64 = v791 - v795;
        let v797: f64 = v790 + v796;
        let v798: f64 = v787 + v797;
        let v799: f64 = v100 * v771;
        let v800: f64 = v103 * v782;
        let v801: f64 = v799 - v800;
        let v802: f64 = v798 + v801;
        let v803: f64 = v81 * v802;
        let v804: f64 = v786 + v803;
        let v805: f64 = v41 * v804;
        let v806: f64 = v704 - v805;
        let v807: f64 = v37 + v806;
        let v808: f64 = v2 * v807;
        let v809: f64 = v26 * v7;
        let v810: f64 = v3 * v12;
        let v811: f64 = v809 - v810;
        let v812: f64 = v17 * v6;
        let v813: f64 = v9 * v5;
        let v814: f64 = v3 * v11;
        let v815: f64 = v813 + v814;
        let v816: f64 = v812 - v815;
        let v817: f64 = v6 * v816;
        let v818: f64 = v5 * v22;
        let v819: f64 = v817 + v818;
        let v820: f64 = v811 + v819;
        let v821: f64 = v33 * v90;
        let v822: f64 = v820 - v821;
        let v823: f64 = v59 * v48;
        let v824: f64 = v63 * v56;
        let v825: f64 = v823 + v824;
        let v826: f64 = v66 * v7;
        let v827: f64 = v825 - v826;
        let v828: f64 = v54 * v76;
        let v829: f64 = v44 * v714;
        let v830: f64 = v828 - v829;
        let v831: f64 = v827 + v830;
        let v832: f64 = v674 * v95;
        let v833: f64 = v80 * v164;
        let v834: f64 = v832 - v833;
        let v835: f64 = v831 + v834;
        let v836: f64 = v103 * v620;
        let v837: f64 = v100 * v663;
        let v838: f64 = v836 + v837;
        let v839: f64 = v835 + v838;
        let v840: f64 = v146 * v700;
        let v841: f64 = v839 - v840;
        let v842: f64 = v822 - v841;
        let v843: f64 = v10 * v842;
        let v844: f64 = v808 + v843;
        let v845: f64 = v0 + v844;
        let v846: f64 = v321 * v345;
        let v847: f64 = v324 * v349;
        let v848: f64 = v846 - v847;
        let v849: f64 = v259 * v848;
        let v850: f64 = v321 * v412;
        let v851: f64 = v324 * v366;
        let v852: f64 = v850 - v851;
        let v853: f64 = v367 * v852;
        let v854: f64 = v352 + v853;
        let v855: f64 = v262 * v854;
        let v856: f64 = v849 + v855;
        let v857: f64 = v175 * v856;
        let v858: f64 = v324 * v345;
        let v859: f64 = v321 * v349;
        let v860: f64 = v858 + v859;
        let v861: f64 = v178 * v860;
        let v862: f64 = v857 + v861;
        let v863: f64 = v321 * v366;
        let v864: f64 = v324 * v412;
        let v865: f64 = v863 + v864;
        let v866: f64 = v259 * v865;
        let v867: f64 = v178 * v866;
        let v868: f64 = v175 * v852;
        let v869: f64 = v867 + v868;
        let v870: f64 = v227 * v869;
        let v871: f64 = v862 + v870;
        let v872: f64 = v103 * v871;
        let v873: f64 = v262 * v848;
        let v874: f64 = v259 * v854;
        let v875: f64 = v873 - v874;
        let v876: f64 = v221 * v869;
        let v877: f64 = v875 - v876;
        let v878: f64 = v100 * v877;
        let v879: f64 = v872 + v878;
        let v880: f64 = v146 * v869;
        let v881: f64 = v879 - v880;
        let v882: f64 = v10 * v881;
        let v883: f64 = v100 * v871;
        let v884: f64 = v103 * v877;
        let v885: f64 = v883 - v884;
        let v886: f64 = v39 * v885;
        let v887: f64 = v175 * v860;
        let v888: f64 = v178 * v856;
        let v889: f64 = v887 - v888;
        let v890: f64 = v262 * v865;
        let v891: f64 = v221 * v890;
        let v892: f64 = v178 * v852;
        let v893: f64 = v175 * v866;
        let v894: f64 = v892 - v893;
        let v895: f64 = v227 * v894;
        let v896: f64 = v891 + v895;
        let v897: f64 = v889 - v896;
        let v898: f64 = v103 * v894;
        let v899: f64 = v100 * v890;
        let v900: f64 = v898 - v899;
        let v901: f64 = v146 * v900;
        let v902: f64 = v897 + v901;
        let v903: f64 = v41 * v902;
        let v904: f64 = v886 + v903;
        let v905: f64 = -0.316_f64;
        let v906: f64 = v100 * v894;
        let v907: f64 = v103 * v890;
        let v908: f64 = v906 + v907;
        let v909: f64 = v41 * v908;
        let v910: f64 = v39 * v869;
        let v911: f64 = v909 - v910;
        let v912: f64 = v905 * v911;
        let v913: f64 = v904 + v912;
        let v914: f64 = v2 * v913;
        let v915: f64 = v882 - v914;
        let v916: f64 = v915 / v352;
        let v917: f64 = tau[6];
        let v918: f64 = v917 - v451;
        let v919: f64 = v916 * v918;
        (
            v754,
            v804,
            v816,
            v841,
            v845,
            v848,
            v852,
            v853,
            v860,
            v863,
            v864,
            v869,
            v875,
            v881,
            v885,
            v897,
            v902,
            v905,
            v908,
            v915,
            v916,
            v918,
            v919,
        )
    };
    let (
        v940,
        v951,
        v955,
        v959,
        v963,
        v965,
        v971,
        v977,
        v981,
        v993,
        v998,
        v1003,
        v1011,
        v1013,
        v1015,
        v1016,
        v1020,
        v1022,
        v1039,
        v1047,
        v1056,
        v1058,
        v1063,
        v1066,
        v1068,
        v1069,
        v1075,
        v1079,
        v1082,
        v1088,
        v1089,
        v1092,
        v1093,
        v1094,
        v1095,
        v1096,
        v1098,
        v1102,
        v1103,
    ) = {
        let v920: f64 = v845 - v919;
        let v921: f64 = v321 * v322;
        let v922: f64 = v324 * v334;
        let v923: f64 = v921 - v922;
        let v924: f64 = v923 * v324;
        let v925: f64 = v321 * v334;
        let v926: f64 = v324 * v358;
        let v927: f64 = v925 - v926;
        let v928: f64 = v927 * v321;
        let v929: f64 = v924 + v928;
        let v930: f64 = v864 + v863;
        let v931: f64 = v367 * v930;
        let v932: f64 = v929 - v931;
        let v933: f64 = v283 + v932;
        let v934: f64 = v259 * v933;
        let v935: f64 = v345 * v324;
        let v936: f64 = v349 * v321;
        let v937: f64 = v935 + v936;
        let v938: f64 = v287 - v937;
        let v939: f64 = v262 * v938;
        let v940: f64 = v934 - v939;
        let v941: f64 = v175 * v940;
        let v942: f64 = v324 * v322;
        let v943: f64 = v942 + v925;
        let v944: f64 = v943 * v324;
        let v945: f64 = v321 * v358;
        let v946: f64 = v922 + v945;
        let v947: f64 = v946 * v321;
        let v948: f64 = v944 + v947;
        let v949: f64 = 0.007743999999999999_f64;
        let v950: f64 = v949 * v453;
        let v951: f64 = 2.0_f64;
        let v952: f64 = v951 * v853;
        let v953: f64 = v950 + v952;
        let v954: f64 = v948 + v953;
        let v955: f64 = v290 + v954;
        let v956: f64 = v178 * v955;
        let v957: f64 = v941 + v956;
        let v958: f64 = v304 - v374;
        let v959: f64 = v259 * v958;
        let v960: f64 = v367 * v453;
        let v961: f64 = v852 + v960;
        let v962: f64 = v435 + v961;
        let v963: f64 = v262 * v962;
        let v964: f64 = v959 + v963;
        let v965: f64 = v178 * v964;
        let v966: f64 = v227 * v965;
        let v967: f64 = v957 + v966;
        let v968: f64 = v103 * v967;
        let v969: f64 = v262 * v933;
        let v970: f64 = v259 * v938;
        let v971: f64 = v969 + v970;
        let v972: f64 = v221 * v965;
        let v973: f64 = v971 - v972;
        let v974: f64 = v100 * v973;
        let v975: f64 = v968 + v974;
        let v976: f64 = v146 * v965;
        let v977: f64 = v975 - v976;
        let v978: f64 = v10 * v977;
        let v979: f64 = v100 * v967;
        let v980: f64 = v103 * v973;
        let v981: f64 = v979 - v980;
        let v982: f64 = v39 * v981;
        let v983: f64 = v175 * v955;
        let v984: f64 = v178 * v940;
        let v985: f64 = v983 - v984;
        let v986: f64 = v259 * v962;
        let v987: f64 = v262 * v958;
        let v988: f64 = v986 - v987;
        let v989: f64 = v221 * v988;
        let v990: f64 = v175 * v964;
        let v991: f64 = v227 * v990;
        let v992: f64 = v989 + v991;
        let v993: f64 = v985 + v992;
        let v994: f64 = v100 * v988;
        let v995: f64 = v103 * v990;
        let v996: f64 = v994 - v995;
        let v997: f64 = v146 * v996;
        let v998: f64 = v993 + v997;
        let v999: f64 = v41 * v998;
        let v1000: f64 = v982 + v999;
        let v1001: f64 = v100 * v990;
        let v1002: f64 = v103 * v988;
        let v1003: f64 = v1001 + v1002;
        let v1004: f64 = v41 * v1003;
        let v1005: f64 = v39 * v965;
        let v1006: f64 = v1004 + v1005;
        let v1007: f64 = v905 * v1006;
        let v1008: f64 = v1000 - v1007;
        let v1009: f64 = v2 * v1008;
        let v1010: f64 = v978 - v1009;
        let v1011: f64 = v860 / v352;
        let v1012: f64 = v915 * v1011;
        let v1013: f64 = v1010 - v1012;
        let v1014: f64 = v860 * v1011;
        let v1015: f64 = v955 - v1014;
        let v1016: f64 = v1013 / v1015;
        let v1017: f64 = tau[5];
        let v1018: f64 = v1017 - v572;
        let v1019: f64 = v1011 * v918;
        let v1020: f64 = v1018 - v1019;
        let v1021: f64 = v1016 * v1020;
        let v1022: f64 = v920 - v1021;
        let v1023: f64 = v923 * v321;
        let v1024: f64 = v927 * v324;
        let v1025: f64 = v1023 - v1024;
        let v1026: f64 = v1025 + v953;
        let v1027: f64 = v1026 - v950;
        let v1028: f64 = v1027 - v853;
        let v1029: f64 = v1028 - v853;
        let v1030: f64 = v260 + v1029;
        let v1031: f64 = v259 * v1030;
        let v1032: f64 = v349 * v324;
        let v1033: f64 = v345 * v321;
        let v1034: f64 = v1032 - v1033;
        let v1035: f64 = v367 * v374;
        let v1036: f64 = v1034 + v1035;
        let v1037: f64 = v272 + v1036;
        let v1038: f64 = v262 * v1037;
        let v1039: f64 = v1031 - v1038;
        let v1040: f64 = v1039 * v262;
        let v1041: f64 = v1035 - v848;
        let v1042: f64 = v272 + v1041;
        let v1043: f64 = v259 * v1042;
        let v1044: f64 = v352 + v953;
        let v1045: f64 = v296 + v1044;
        let v1046: f64 = v262 * v1045;
        let v1047: f64 = v1043 - v1046;
        let v1048: f64 = v1047 * v259;
        let v1049: f64 = v1040 + v1048;
        let v1050: f64 = v199 + v1049;
        let v1051: f64 = v175 * v1050;
        let v1052: f64 = v943 * v321;
        let v1053: f64 = v946 * v324;
        let v1054: f64 = v1052 - v1053;
        let v1055: f64 = v1054 - v931;
        let v1056: f64 = v283 + v1055;
        let v1057: f64 = v1056 * v262;
        let v1058: f64 = v287 - v860;
        let v1059: f64 = v1058 * v259;
        let v1060: f64 = v1057 + v1059;
        let v1061: f64 = v203 - v1060;
        let v1062: f64 = v178 * v1061;
        let v1063: f64 = v1051 - v1062;
        let v1064: f64 = v306 + v930;
        let v1065: f64 = v220 - v1064;
        let v1066: f64 = v178 * v1065;
        let v1067: f64 = v491 + v988;
        let v1068: f64 = v175 * v1067;
        let v1069: f64 = v1066 - v1068;
        let v1070: f64 = v227 * v1069;
        let v1071: f64 = v1063 + v1070;
        let v1072: f64 = v103 * v1071;
        let v1073: f64 = v262 * v1030;
        let v1074: f64 = v259 * v1037;
        let v1075: f64 = v1073 + v1074;
        let v1076: f64 = v1075 * v262;
        let v1077: f64 = v262 * v1042;
        let v1078: f64 = v259 * v1045;
        let v1079: f64 = v1077 + v1078;
        let v1080: f64 = v1079 * v259;
        let v1081: f64 = v1076 + v1080;
        let v1082: f64 = v206 + v1081;
        let v1083: f64 = v221 * v1069;
        let v1084: f64 = v1082 - v1083;
        let v1085: f64 = v100 * v1084;
        let v1086: f64 = v1072 + v1085;
        let v1087: f64 = v146 * v1069;
        let v1088: f64 = v1086 - v1087;
        let v1089: f64 = v10 * v1088;
        let v1090: f64 = v100 * v1071;
        let v1091: f64 = v103 * v1084;
        let v1092: f64 = v1090 - v1091;
        let v1093: f64 = v39 * v1092;
        let v1094: f64 = v175 * v1065;
        let v1095: f64 = v178 * v1067;
        let v1096: f64 = v1094 + v1095;
        let v1097: f64 = v103 * v1096;
        let v1098: f64 = v146 * v1097;
        let v1099: f64 = v227 * v1096;
        let v1100: f64 = v178 * v1050;
        let v1101: f64 = v175 * v1061;
        let v1102: f64 = v1100 + v1101;
        let v1103: f64 = v1099 - v1102;
        (
            v940,
            v951,
            v955,
            v959,
            v963,
            v965,
            v971,
            v977,
            v981,
            v993,
            v998,
            v1003,
            v1011,
            v1013,
            v1015,
            v1016,
            v1020,
            v1022,
            v1039,
            v1047,
            v1056,
            v1058,
            v1063,
            v1066,
            v1068,
            v1069,
            v1075,
            v1079,
            v1082,
            v1088,
            v1089,
            v1092,
            v1093,
            v1094,
            v1095,
            v1096,
            v1098,
            v1102,
            v1103,
        )
    };
    let (
        v1104,
        v1107,
        v1115,
        v1120,
        v1122,
        v1126,
        v1127,
        v1133,
        v1136,
        v1137,
        v1160,
        v1172,
        v1176,
        v1180,
        v1184,
        v1189,
        v1195,
        v1200,
        v1209,
        v1210,
        v1211,
        v1214,
        v1215,
        v1216,
        v1222,
        v1227,
        v1234,
        v1236,
        v1242,
        v1243,
        v1251,
        v1253,
        v1258,
        v1263,
        v1275,
        v1277,
        v1278,
        v1282,
        v1283,
        v1287,
    ) = {
        let v1104: f64 = v1098 - v1103;
        let v1105: f64 = v41 * v1104;
        let v1106: f64 = v1093 - v1105;
        let v1107: f64 = v100 * v1096;
        let v1108: f64 = v41 * v1107;
        let v1109: f64 = v39 * v1069;
        let v1110: f64 = v1108 + v1109;
        let v1111: f64 = v905 * v1110;
        let v1112: f64 = v1106 - v1111;
        let v1113: f64 = v2 * v1112;
        let v1114: f64 = v1089 - v1113;
        let v1115: f64 = v875 / v352;
        let v1116: f64 = v915 * v1115;
        let v1117: f64 = v1114 - v1116;
        let v1118: f64 = v875 * v1011;
        let v1119: f64 = v971 - v1118;
        let v1120: f64 = v1119 / v1015;
        let v1121: f64 = v1013 * v1120;
        let v1122: f64 = v1117 - v1121;
        let v1123: f64 = v875 * v1115;
        let v1124: f64 = v1082 - v1123;
        let v1125: f64 = v1119 * v1120;
        let v1126: f64 = v1124 - v1125;
        let v1127: f64 = v1122 / v1126;
        let v1128: f64 = tau[4];
        let v1129: f64 = v1128 - v657;
        let v1130: f64 = v1115 * v918;
        let v1131: f64 = v1129 - v1130;
        let v1132: f64 = v1120 * v1020;
        let v1133: f64 = v1131 - v1132;
        let v1134: f64 = v1127 * v1133;
        let v1135: f64 = v1022 - v1134;
        let v1136: f64 = v1095 + v1094;
        let v1137: f64 = v221 * v1136;
        let v1138: f64 = v1039 * v259;
        let v1139: f64 = v1047 * v262;
        let v1140: f64 = v1138 - v1139;
        let v1141: f64 = v176 + v1140;
        let v1142: f64 = v175 * v1141;
        let v1143: f64 = v1058 * v262;
        let v1144: f64 = v1056 * v259;
        let v1145: f64 = v1143 - v1144;
        let v1146: f64 = v188 + v1145;
        let v1147: f64 = v178 * v1146;
        let v1148: f64 = v1142 - v1147;
        let v1149: f64 = v1148 * v178;
        let v1150: f64 = v188 - v940;
        let v1151: f64 = v175 * v1150;
        let v1152: f64 = v212 + v955;
        let v1153: f64 = v178 * v1152;
        let v1154: f64 = v1151 - v1153;
        let v1155: f64 = v1154 * v175;
        let v1156: f64 = v1149 + v1155;
        let v1157: f64 = v1137 - v1156;
        let v1158: f64 = v124 + v1157;
        let v1159: f64 = v103 * v1158;
        let v1160: f64 = v227 * v1136;
        let v1161: f64 = v1075 * v259;
        let v1162: f64 = v1079 * v262;
        let v1163: f64 = v1161 - v1162;
        let v1164: f64 = v199 + v1163;
        let v1165: f64 = v1164 * v178;
        let v1166: f64 = v203 - v971;
        let v1167: f64 = v1166 * v175;
        let v1168: f64 = v1165 + v1167;
        let v1169: f64 = v1160 - v1168;
        let v1170: f64 = v128 + v1169;
        let v1171: f64 = v100 * v1170;
        let v1172: f64 = v1159 + v1171;
        let v1173: f64 = v10 * v1172;
        let v1174: f64 = v100 * v1158;
        let v1175: f64 = v103 * v1170;
        let v1176: f64 = v1174 - v1175;
        let v1177: f64 = v39 * v1176;
        let v1178: f64 = v178 * v1141;
        let v1179: f64 = v175 * v1146;
        let v1180: f64 = v1178 + v1179;
        let v1181: f64 = v1180 * v178;
        let v1182: f64 = v178 * v1150;
        let v1183: f64 = v175 * v1152;
        let v1184: f64 = v1182 + v1183;
        let v1185: f64 = v1184 * v175;
        let v1186: f64 = v1181 + v1185;
        let v1187: f64 = 0.15426225000000002_f64;
        let v1188: f64 = v506 + v453;
        let v1189: f64 = v489 + v1188;
        let v1190: f64 = v1187 * v1189;
        let v1191: f64 = v1068 - v1066;
        let v1192: f64 = v221 * v1191;
        let v1193: f64 = v963 + v959;
        let v1194: f64 = v235 + v1193;
        let v1195: f64 = v227 * v1194;
        let v1196: f64 = v1192 + v1195;
        let v1197: f64 = v951 * v1196;
        let v1198: f64 = v1190 + v1197;
        let v1199: f64 = v1186 + v1198;
        let v1200: f64 = v131 + v1199;
        let v1201: f64 = v221 * v1189;
        let v1202: f64 = v1191 + v1201;
        let v1203: f64 = v637 + v1202;
        let v1204: f64 = v100 * v1203;
        let v1205: f64 = v227 * v1189;
        let v1206: f64 = v1194 + v1205;
        let v1207: f64 = v145 + v1206;
        let v1208: f64 = v103 * v1207;
        let v1209: f64 = v1204 - v1208;
        let v1210: f64 = v146 * v1209;
        let v1211: f64 = v1200 + v1210;
        let v1212: f64 = v41 * v1211;
        let v1213: f64 = v1177 + v1212;
        let v1214: f64 = v100 * v1207;
        let v1215: f64 = v103 * v1203;
        let v1216: f64 = v1214 + v1215;
        let v1217: f64 = v41 * v1216;
        let v1218: f64 = v905 * v1217;
        let v1219: f64 = v1213 - v1218;
        let v1220: f64 = v2 * v1219;
        let v1221: f64 = v1173 - v1220;
        let v1222: f64 = v897 / v352;
        let v1223: f64 = v915 * v1222;
        let v1224: f64 = v1221 - v1223;
        let v1225: f64 = v897 * v1011;
        let v1226: f64 = v993 - v1225;
        let v1227: f64 = v1226 / v1015;
        let v1228: f64 = v1013 * v1227;
        let v1229: f64 = v1224 - v1228;
        let v1230: f64 = v897 * v1115;
        let v1231: f64 = v1103 - v1230;
        let v1232: f64 = v1226 * v1120;
        let v1233: f64 = v1231 - v1232;
        let v1234: f64 = v1233 / v1126;
        let v1235: f64 = v1122 * v1234;
        let v1236: f64 = v1229 - v1235;
        let v1237: f64 = v897 * v1222;
        let v1238: f64 = v1200 - v1237;
        let v1239: f64 = v1226 * v1227;
        let v1240: f64 = v1238 - v1239;
        let v1241: f64 = v1233 * v1234;
        let v1242: f64 = v1240 - v1241;
        let v1243: f64 = v1236 / v1242;
        let v1244: f64 = tau[3];
        let v1245: f64 = v1244 - v754;
        let v1246: f64 = v1222 * v918;
        let v1247: f64 = v1245 - v1246;
        let v1248: f64 = v1227 * v1020;
        let v1249: f64 = v1247 - v1248;
        let v1250: f64 = v1234 * v1133;
        let v1251: f64 = v1249 - v1250;
        let v1252: f64 = v1243 * v1251;
        let v1253: f64 = v1135 - v1252;
        let v1254: f64 = v1148 * v175;
        let v1255: f64 = v1154 * v178;
        let v1256: f64 = v1254 - v1255;
        let v1257: f64 = v1256 + v1198;
        let v1258: f64 = 0.006806250000000001_f64;
        let v1259: f64 = v1258 * v1189;
        let v1260: f64 = v1257 - v1259;
        let v1261: f64 = v1260 - v1192;
        let v1262: f64 = v1261 - v1192;
        let v1263: f64 = v101 + v1262;
        let v1264: f64 = v103 * v1263;
        let v1265: f64 = v1164 * v175;
        let v1266: f64 = v1166 * v178;
        let v1267: f64 = v1265 - v1266;
        let v1268: f64 = -0.03168_f64;
        let v1269: f64 = v1268 * v1189;
        let v1270: f64 = v1267 - v1269;
        let v1271: f64 = v221 * v1194;
        let v1272: f64 = v1270 - v1271;
        let v1273: f64 = v227 * v1191;
        let v1274: f64 = v1272 - v1273;
        let v1275: f64 = v113 + v1274;
        let v1276: f64 = v100 * v1275;
        let v1277: f64 = v1264 + v1276;
        let v1278: f64 = v1277 * v103;
        let v1279: f64 = v1063 - v1269;
        let v1280: f64 = v1279 - v1273;
        let v1281: f64 = v1280 - v1271;
        let v1282: f64 = v113 + v1281;
        let v1283: f64 = v103 * v1282;
        let v1284: f64 = v1082 + v1198;
        let v1285: f64 = 0.147456_f64;
        let v1286: f64 = v1285 * v1189;
        let v1287: f64 = v1284 - v1286;
        (
            v1104,
            v1107,
            v1115,
            v1120,
            v1122,
            v1126,
            v1127,
            v1133,
            v1136,
            v1137,
            v1160,
            v1172,
            v1176,
            v1180,
            v1184,
            v1189,
            v1195,
            v1200,
            v1209,
            v1210,
            v1211,
            v1214,
            v1215,
            v1216,
            v1222,
            v1227,
            v1234,
            v1236,
            v1242,
            v1243,
            v1251,
            v1253,
            v1258,
            v1263,
            v1275,
            v1277,
            v1278,
            v1282,
            v1283,
            v1287,
        )
    };
    let (
        v1295,
        v1300,
        v1311,
        v1314,
        v1326,
        v1337,
        v1338,
        v1341,
        v1346,
        v1353,
        v1362,
        v1364,
        v1372,
        v1373,
        v1383,
        v1385,
        v1393,
        v1400,
        v1402,
        v1405,
        v1408,
        v1410,
        v1419,
        v1421,
        v1424,
        v1425,
        v1439,
        v1440,
        v1452,
        v1453,
        v1467,
        v1468,
        v1470,
        v1471,
    ) = {
        let v1288: f64 = v1287 - v1195;
        let v1289: f64 = v1288 - v1195;
        let v1290: f64 = v137 + v1289;
        let v1291: f64 = v100 * v1290;
        let v1292: f64 = v1283 + v1291;
        let v1293: f64 = v1292 * v100;
        let v1294: f64 = v1278 + v1293;
        let v1295: f64 = v697 + v1189;
        let v1296: f64 = v1258 * v1295;
        let v1297: f64 = v951 * v1210;
        let v1298: f64 = v1296 + v1297;
        let v1299: f64 = v1294 + v1298;
        let v1300: f64 = v66 + v1299;
        let v1301: f64 = v10 * v1300;
        let v1302: f64 = v100 * v1263;
        let v1303: f64 = v103 * v1275;
        let v1304: f64 = v1302 - v1303;
        let v1305: f64 = v1304 * v103;
        let v1306: f64 = v100 * v1282;
        let v1307: f64 = v103 * v1290;
        let v1308: f64 = v1306 - v1307;
        let v1309: f64 = v1308 * v100;
        let v1310: f64 = v1305 + v1309;
        let v1311: f64 = v1215 + v1214;
        let v1312: f64 = v146 * v1311;
        let v1313: f64 = v1310 - v1312;
        let v1314: f64 = v59 + v1313;
        let v1315: f64 = v39 * v1314;
        let v1316: f64 = v1184 * v178;
        let v1317: f64 = v1180 * v175;
        let v1318: f64 = v1316 - v1317;
        let v1319: f64 = v1318 + v1137;
        let v1320: f64 = v124 + v1319;
        let v1321: f64 = v1320 * v103;
        let v1322: f64 = v1160 - v1102;
        let v1323: f64 = v128 + v1322;
        let v1324: f64 = v1323 * v100;
        let v1325: f64 = v1321 + v1324;
        let v1326: f64 = v63 - v1325;
        let v1327: f64 = v41 * v1326;
        let v1328: f64 = v1315 - v1327;
        let v1329: f64 = v146 * v1295;
        let v1330: f64 = v1209 + v1329;
        let v1331: f64 = v674 + v1330;
        let v1332: f64 = v39 * v1331;
        let v1333: f64 = v153 - v1136;
        let v1334: f64 = v80 - v1333;
        let v1335: f64 = v41 * v1334;
        let v1336: f64 = v1332 - v1335;
        let v1337: f64 = v905 * v1336;
        let v1338: f64 = v1328 + v1337;
        let v1339: f64 = v2 * v1338;
        let v1340: f64 = v1301 - v1339;
        let v1341: f64 = v881 / v352;
        let v1342: f64 = v915 * v1341;
        let v1343: f64 = v1340 - v1342;
        let v1344: f64 = v881 * v1011;
        let v1345: f64 = v977 - v1344;
        let v1346: f64 = v1345 / v1015;
        let v1347: f64 = v1013 * v1346;
        let v1348: f64 = v1343 - v1347;
        let v1349: f64 = v881 * v1115;
        let v1350: f64 = v1088 - v1349;
        let v1351: f64 = v1345 * v1120;
        let v1352: f64 = v1350 - v1351;
        let v1353: f64 = v1352 / v1126;
        let v1354: f64 = v1122 * v1353;
        let v1355: f64 = v1348 - v1354;
        let v1356: f64 = v881 * v1222;
        let v1357: f64 = v1172 - v1356;
        let v1358: f64 = v1345 * v1227;
        let v1359: f64 = v1357 - v1358;
        let v1360: f64 = v1352 * v1234;
        let v1361: f64 = v1359 - v1360;
        let v1362: f64 = v1361 / v1242;
        let v1363: f64 = v1236 * v1362;
        let v1364: f64 = v1355 - v1363;
        let v1365: f64 = v881 * v1341;
        let v1366: f64 = v1300 - v1365;
        let v1367: f64 = v1345 * v1346;
        let v1368: f64 = v1366 - v1367;
        let v1369: f64 = v1352 * v1353;
        let v1370: f64 = v1368 - v1369;
        let v1371: f64 = v1361 * v1362;
        let v1372: f64 = v1370 - v1371;
        let v1373: f64 = v1364 / v1372;
        let v1374: f64 = tau[2];
        let v1375: f64 = v1374 - v841;
        let v1376: f64 = v1341 * v918;
        let v1377: f64 = v1375 - v1376;
        let v1378: f64 = v1346 * v1020;
        let v1379: f64 = v1377 - v1378;
        let v1380: f64 = v1353 * v1133;
        let v1381: f64 = v1379 - v1380;
        let v1382: f64 = v1362 * v1251;
        let v1383: f64 = v1381 - v1382;
        let v1384: f64 = v1373 * v1383;
        let v1385: f64 = v1253 - v1384;
        let v1386: f64 = v1304 * v100;
        let v1387: f64 = v1308 * v103;
        let v1388: f64 = v1386 - v1387;
        let v1389: f64 = v1388 + v1298;
        let v1390: f64 = v1389 - v1296;
        let v1391: f64 = v1390 - v1210;
        let v1392: f64 = v1391 - v1210;
        let v1393: f64 = v40 + v1392;
        let v1394: f64 = v39 * v1393;
        let v1395: f64 = v1323 * v103;
        let v1396: f64 = v1320 * v100;
        let v1397: f64 = v1395 - v1396;
        let v1398: f64 = v146 * v1333;
        let v1399: f64 = v1397 + v1398;
        let v1400: f64 = v50 + v1399;
        let v1401: f64 = v41 * v1400;
        let v1402: f64 = v1394 - v1401;
        let v1403: f64 = v1402 * v41;
        let v1404: f64 = v1398 - v1176;
        let v1405: f64 = v50 + v1404;
        let v1406: f64 = v39 * v1405;
        let v1407: f64 = v1200 + v1298;
        let v1408: f64 = v72 + v1407;
        let v1409: f64 = v41 * v1408;
        let v1410: f64 = v1406 - v1409;
        let v1411: f64 = v1410 * v39;
        let v1412: f64 = v1403 + v1411;
        let v1413: f64 = v17 + v1412;
        let v1414: f64 = v2 * v1413;
        let v1415: f64 = v1277 * v100;
        let v1416: f64 = v1292 * v103;
        let v1417: f64 = v1415 - v1416;
        let v1418: f64 = v1417 - v1312;
        let v1419: f64 = v59 + v1418;
        let v1420: f64 = v1419 * v41;
        let v1421: f64 = v63 - v1172;
        let v1422: f64 = v1421 * v39;
        let v1423: f64 = v1420 + v1422;
        let v1424: f64 = v41 * v1331;
        let v1425: f64 = v39 * v1334;
        let v1426: f64 = v1424 + v1425;
        let v1427: f64 = v905 * v1426;
        let v1428: f64 = v1423 + v1427;
        let v1429: f64 = v19 - v1428;
        let v1430: f64 = v10 * v1429;
        let v1431: f64 = v1414 + v1430;
        let v1432: f64 = v41 * v885;
        let v1433: f64 = v39 * v902;
        let v1434: f64 = v1432 - v1433;
        let v1435: f64 = v39 * v908;
        let v1436: f64 = v41 * v869;
        let v1437: f64 = v1435 + v1436;
        let v1438: f64 = v905 * v1437;
        let v1439: f64 = v1434 - v1438;
        let v1440: f64 = v1439 / v352;
        let v1441: f64 = v915 * v1440;
        let v1442: f64 = v1431 + v1441;
        let v1443: f64 = v41 * v981;
        let v1444: f64 = v39 * v998;
        let v1445: f64 = v1443 - v1444;
        let v1446: f64 = v41 * v965;
        let v1447: f64 = v39 * v1003;
        let v1448: f64 = v1446 - v1447;
        let v1449: f64 = v905 * v1448;
        let v1450: f64 = v1445 - v1449;
        let v1451: f64 = v1439 * v1011;
        let v1452: f64 = v1450 - v1451;
        let v1453: f64 = v1452 / v1015;
        let v1454: f64 = v1013 * v1453;
        let v1455: f64 = v1442 + v1454;
        let v1456: f64 = v41 * v1092;
        let v1457: f64 = v39 * v1104;
        let v1458: f64 = v1456 + v1457;
        let v1459: f64 = v41 * v1069;
        let v1460: f64 = v39 * v1107;
        let v1461: f64 = v1459 - v1460;
        let v1462: f64 = v905 * v1461;
        let v1463: f64 = v1458 - v1462;
        let v1464: f64 = v1439 * v1115;
        let v1465: f64 = v1463 - v1464;
        let v1466: f64 = v1452 * v1120;
        let v1467: f64 = v1465 - v1466;
        let v1468: f64 = v1467 / v1126;
        let v1469: f64 = v1122 * v1468;
        let v1470: f64 = v1455 + v1469;
        let v1471: f64 = v41 * v1176;
        (
            v1295,
            v1300,
            v1311,
            v1314,
            v1326,
            v1337,
            v1338,
            v1341,
            v1346,
            v1353,
            v1362,
            v1364,
            v1372,
            v1373,
            v1383,
            v1385,
            v1393,
            v1400,
            v1402,
            v1405,
            v1408,
            v1410,
            v1419,
            v1421,
            v1424,
            v1425,
            v1439,
            v1440,
            v1452,
            v1453,
            v1467,
            v1468,
            v1470,
            v1471,
        )
    };
    let (v1602, v1605, v1610, v1617, v1626, v1637, v1650) = {
        let v1472: f64 = v39 * v1211;
        let v1473: f64 = v1471 - v1472;
        let v1474: f64 = v39 * v1216;
        let v1475: f64 = v905 * v1474;
        let v1476: f64 = v1473 + v1475;
        let v1477: f64 = v1439 * v1222;
        let v1478: f64 = v1476 - v1477;
        let v1479: f64 = v1452 * v1227;
        let v1480: f64 = v1478 - v1479;
        let v1481: f64 = v1467 * v1234;
        let v1482: f64 = v1480 - v1481;
        let v1483: f64 = v1482 / v1242;
        let v1484: f64 = v1236 * v1483;
        let v1485: f64 = v1470 + v1484;
        let v1486: f64 = v41 * v1314;
        let v1487: f64 = v39 * v1326;
        let v1488: f64 = v1486 + v1487;
        let v1489: f64 = v1425 + v1424;
        let v1490: f64 = v905 * v1489;
        let v1491: f64 = v1488 + v1490;
        let v1492: f64 = v1439 * v1341;
        let v1493: f64 = v1491 - v1492;
        let v1494: f64 = v1452 * v1346;
        let v1495: f64 = v1493 - v1494;
        let v1496: f64 = v1467 * v1353;
        let v1497: f64 = v1495 - v1496;
        let v1498: f64 = v1482 * v1362;
        let v1499: f64 = v1497 - v1498;
        let v1500: f64 = v1499 / v1372;
        let v1501: f64 = v1364 * v1500;
        let v1502: f64 = v1485 + v1501;
        let v1503: f64 = v41 * v1393;
        let v1504: f64 = v39 * v1400;
        let v1505: f64 = v1503 + v1504;
        let v1506: f64 = v1505 * v41;
        let v1507: f64 = v41 * v1405;
        let v1508: f64 = v39 * v1408;
        let v1509: f64 = v1507 + v1508;
        let v1510: f64 = v1509 * v39;
        let v1511: f64 = v1506 + v1510;
        let v1512: f64 = 0.099856_f64;
        let v1513: f64 = v667 + v1295;
        let v1514: f64 = v1512 * v1513;
        let v1515: f64 = v89 + v1311;
        let v1516: f64 = v905 * v1515;
        let v1517: f64 = v951 * v1516;
        let v1518: f64 = v1514 - v1517;
        let v1519: f64 = v1511 + v1518;
        let v1520: f64 = v15 + v1519;
        let v1521: f64 = v1439 * v1440;
        let v1522: f64 = v1520 - v1521;
        let v1523: f64 = v1452 * v1453;
        let v1524: f64 = v1522 - v1523;
        let v1525: f64 = v1467 * v1468;
        let v1526: f64 = v1524 - v1525;
        let v1527: f64 = v1482 * v1483;
        let v1528: f64 = v1526 - v1527;
        let v1529: f64 = v1499 * v1500;
        let v1530: f64 = v1528 - v1529;
        let v1531: f64 = v1502 / v1530;
        let v1532: f64 = tau[1];
        let v1533: f64 = v19 * v7;
        let v1534: f64 = v17 * v12;
        let v1535: f64 = v1533 - v1534;
        let v1536: f64 = v11 * v816;
        let v1537: f64 = v5 * v29;
        let v1538: f64 = v1536 - v1537;
        let v1539: f64 = v1535 + v1538;
        let v1540: f64 = params[12];
        let v1541: f64 = v1540 * v90;
        let v1542: f64 = params[11];
        let v1543: f64 = v1542 * v35;
        let v1544: f64 = v1541 - v1543;
        let v1545: f64 = v1539 + v1544;
        let v1546: f64 = v41 * v703;
        let v1547: f64 = v39 * v804;
        let v1548: f64 = v1546 + v1547;
        let v1549: f64 = v1545 + v1548;
        let v1550: f64 = v1532 - v1549;
        let v1551: f64 = v1440 * v918;
        let v1552: f64 = v1550 - v1551;
        let v1553: f64 = v1453 * v1020;
        let v1554: f64 = v1552 - v1553;
        let v1555: f64 = v1468 * v1133;
        let v1556: f64 = v1554 - v1555;
        let v1557: f64 = v1483 * v1251;
        let v1558: f64 = v1556 - v1557;
        let v1559: f64 = v1500 * v1383;
        let v1560: f64 = v1558 - v1559;
        let v1561: f64 = v1531 * v1560;
        let v1562: f64 = v1385 + v1561;
        let v1563: f64 = params[9];
        let v1564: f64 = v1402 * v39;
        let v1565: f64 = v1410 * v41;
        let v1566: f64 = v1564 - v1565;
        let v1567: f64 = v1566 + v1518;
        let v1568: f64 = v9 + v1567;
        let v1569: f64 = v2 * v1568;
        let v1570: f64 = v1421 * v41;
        let v1571: f64 = v1419 * v39;
        let v1572: f64 = v1570 - v1571;
        let v1573: f64 = v1572 - v1337;
        let v1574: f64 = v3 + v1573;
        let v1575: f64 = v10 * v1574;
        let v1576: f64 = v1569 + v1575;
        let v1577: f64 = v1576 * v2;
        let v1578: f64 = v3 - v1338;
        let v1579: f64 = v2 * v1578;
        let v1580: f64 = v1300 + v1518;
        let v1581: f64 = v1580 - v1514;
        let v1582: f64 = v1581 + v1516;
        let v1583: f64 = v1582 + v1516;
        let v1584: f64 = v26 + v1583;
        let v1585: f64 = v10 * v1584;
        let v1586: f64 = v1579 + v1585;
        let v1587: f64 = v1586 * v10;
        let v1588: f64 = v1577 + v1587;
        let v1589: f64 = v1563 + v1588;
        let v1590: f64 = v915 * v916;
        let v1591: f64 = v1589 - v1590;
        let v1592: f64 = v1013 * v1016;
        let v1593: f64 = v1591 - v1592;
        let v1594: f64 = v1122 * v1127;
        let v1595: f64 = v1593 - v1594;
        let v1596: f64 = v1236 * v1243;
        let v1597: f64 = v1595 - v1596;
        let v1598: f64 = v1364 * v1373;
        let v1599: f64 = v1597 - v1598;
        let v1600: f64 = v1502 * v1531;
        let v1601: f64 = v1599 - v1600;
        let v1602: f64 = v1562 / v1601;
        let v1603: f64 = v1560 / v1530;
        let v1604: f64 = v1531 * v1602;
        let v1605: f64 = v1603 + v1604;
        let v1606: f64 = v1383 / v1372;
        let v1607: f64 = v1373 * v1602;
        let v1608: f64 = v1606 - v1607;
        let v1609: f64 = v1500 * v1605;
        let v1610: f64 = v1608 - v1609;
        let v1611: f64 = v1251 / v1242;
        let v1612: f64 = v1243 * v1602;
        let v1613: f64 = v1611 - v1612;
        let v1614: f64 = v1483 * v1605;
        let v1615: f64 = v1613 - v1614;
        let v1616: f64 = v1362 * v1610;
        let v1617: f64 = v1615 - v1616;
        let v1618: f64 = v1133 / v1126;
        let v1619: f64 = v1127 * v1602;
        let v1620: f64 = v1618 - v1619;
        let v1621: f64 = v1468 * v1605;
        let v1622: f64 = v1620 - v1621;
        let v1623: f64 = v1353 * v1610;
        let v1624: f64 = v1622 - v1623;
        let v1625: f64 = v1234 * v1617;
        let v1626: f64 = v1624 - v1625;
        let v1627: f64 = v1020 / v1015;
        let v1628: f64 = v1016 * v1602;
        let v1629: f64 = v1627 - v1628;
        let v1630: f64 = v1453 * v1605;
        let v1631: f64 = v1629 - v1630;
        let v1632: f64 = v1346 * v1610;
        let v1633: f64 = v1631 - v1632;
        let v1634: f64 = v1227 * v1617;
        let v1635: f64 = v1633 - v1634;
        let v1636: f64 = v1120 * v1626;
        let v1637: f64 = v1635 - v1636;
        let v1638: f64 = v918 / v352;
        let v1639: f64 = v916 * v1602;
        let v1640: f64 = v1638 - v1639;
        let v1641: f64 = v1440 * v1605;
        let v1642: f64 = v1640 - v1641;
        let v1643: f64 = v1341 * v1610;
        let v1644: f64 = v1642 - v1643;
        let v1645: f64 = v1222 * v1617;
        let v1646: f64 = v1644 - v1645;
        let v1647: f64 = v1115 * v1626;
        let v1648: f64 = v1646 - v1647;
        let v1649: f64 = v1011 * v1637;
        let v1650: f64 = v1648 - v1649;
        (v1602, v1605, v1610, v1617, v1626, v1637, v1650)
    };
    [v1602, v1605, v1610, v1617, v1626, v1637, v1650]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/panda_parametric.json")
);
