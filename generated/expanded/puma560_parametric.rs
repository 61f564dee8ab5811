// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/puma560_parametric.json")` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "puma560";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "PUMA 560, 6R, standard DH with the published inertial parameters";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 6;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "armdyn-codegen 0.1.0";
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
/// The task: the rows of the geometric Jacobian (`vx vy vz wx wy wz`) its end
/// effector is controlled in (the description's `task`).
pub const TASK_ROWS: [usize; 6] = [0, 1, 2, 3, 4, 5];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 6] = [
    ("mass_matrix", 503, 10),
    ("coriolis_matrix", 4214, 10),
    ("coriolis", 650, 10),
    ("gravity", 125, 10),
    ("inverse_dynamics", 690, 10),
    ("forward_dynamics", 1307, 10),
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
/// Operation count: 503 floating-point operations, 10 trig calls.
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
        v11,
        v30,
        v43,
        v47,
        v53,
        v55,
        v60,
        v74,
        v76,
        v82,
        v87,
        v89,
        v96,
        v97,
        v99,
        v107,
        v108,
        v109,
        v110,
        v117,
        v119,
        v123,
        v125,
        v126,
        v128,
        v130,
        v132,
        v144,
        v149,
        v150,
        v156,
        v157,
        v158,
        v161,
        v162,
        v165,
        v166,
        v167,
        v170,
        v172,
        v173,
        v177,
        v182,
        v184,
        v186,
        v187,
        v188,
        v189,
        v190,
        v191,
        v247,
    ) = {
        let v0: f64 = params[7];
        let v1: f64 = q[1];
        let (v2, v247): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = params[14];
        let v4: f64 = q[2];
        let (v132, v5): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
        let v6: f64 = params[24];
        let v7: f64 = q[3];
        let (v55, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v7);
        let v9: f64 = params[34];
        let v10: f64 = q[4];
        let (v30, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v10);
        let v12: f64 = params[44];
        let v13: f64 = q[5];
        let (v17, v14): (f64, f64) = ::armdyn_runtime::libm::sincos(v13);
        let v15: f64 = params[54];
        let v16: f64 = v14 * v15;
        let v18: f64 = params[55];
        let v19: f64 = v17 * v18;
        let v20: f64 = v16 - v19;
        let v21: f64 = v20 * v14;
        let v22: f64 = v14 * v18;
        let v23: f64 = params[57];
        let v24: f64 = v17 * v23;
        let v25: f64 = v22 - v24;
        let v26: f64 = v25 * v17;
        let v27: f64 = v21 - v26;
        let v28: f64 = v12 + v27;
        let v29: f64 = v11 * v28;
        let v31: f64 = params[46];
        let v32: f64 = params[56];
        let v33: f64 = v32 * v14;
        let v34: f64 = params[58];
        let v35: f64 = v34 * v17;
        let v36: f64 = v33 - v35;
        let v37: f64 = v31 + v36;
        let v38: f64 = v30 * v37;
        let v39: f64 = v29 - v38;
        let v40: f64 = v39 * v11;
        let v41: f64 = v14 * v32;
        let v42: f64 = v17 * v34;
        let v43: f64 = v41 - v42;
        let v44: f64 = v31 + v43;
        let v45: f64 = v11 * v44;
        let v46: f64 = params[49];
        let v47: f64 = params[59];
        let v48: f64 = v46 + v47;
        let v49: f64 = v30 * v48;
        let v50: f64 = v45 - v49;
        let v51: f64 = v50 * v30;
        let v52: f64 = v40 - v51;
        let v53: f64 = v9 + v52;
        let v54: f64 = v8 * v53;
        let v56: f64 = params[36];
        let v57: f64 = params[48];
        let v58: f64 = v17 * v32;
        let v59: f64 = v14 * v34;
        let v60: f64 = v58 + v59;
        let v61: f64 = v57 + v60;
        let v62: f64 = v61 * v30;
        let v63: f64 = params[45];
        let v64: f64 = v17 * v15;
        let v65: f64 = v64 + v22;
        let v66: f64 = v65 * v14;
        let v67: f64 = v14 * v23;
        let v68: f64 = v19 + v67;
        let v69: f64 = v68 * v17;
        let v70: f64 = v66 - v69;
        let v71: f64 = v63 + v70;
        let v72: f64 = v71 * v11;
        let v73: f64 = v62 - v72;
        let v74: f64 = v56 + v73;
        let v75: f64 = v55 * v74;
        let v76: f64 = v54 + v75;
        let v77: f64 = v76 * v8;
        let v78: f64 = v20 * v17;
        let v79: f64 = v25 * v14;
        let v80: f64 = v78 + v79;
        let v81: f64 = v63 + v80;
        let v82: f64 = v11 * v81;
        let v83: f64 = v32 * v17;
        let v84: f64 = v34 * v14;
        let v85: f64 = v83 + v84;
        let v86: f64 = v57 + v85;
        let v87: f64 = v30 * v86;
        let v88: f64 = v82 - v87;
        let v89: f64 = v56 - v88;
        let v90: f64 = v8 * v89;
        let v91: f64 = params[39];
        let v92: f64 = params[47];
        let v93: f64 = v65 * v17;
        let v94: f64 = v68 * v14;
        let v95: f64 = v93 + v94;
        let v96: f64 = v92 + v95;
        let v97: f64 = v91 + v96;
        let v98: f64 = v55 * v97;
        let v99: f64 = v90 + v98;
        let v100: f64 = v99 * v55;
        let v101: f64 = v77 + v100;
        let v102: f64 = 0.18645124000000002_f64;
        let v103: f64 = params[30];
        let v104: f64 = params[40];
        let v105: f64 = params[50];
        let v106: f64 = v104 + v105;
        let v107: f64 = v103 + v106;
        let v108: f64 = v102 * v107;
        let v109: f64 = 2.0_f64;
        let v110: f64 = 0.4318_f64;
        let v111: f64 = params[32];
        let v112: f64 = params[41];
        let v113: f64 = params[51];
        let v114: f64 = v14 * v113;
        let v115: f64 = params[52];
        let v116: f64 = v17 * v115;
        let v117: f64 = v114 - v116;
        let v118: f64 = v112 + v117;
        let v119: f64 = v30 * v118;
        let v120: f64 = params[43];
        let v121: f64 = params[53];
        let v122: f64 = v120 + v121;
        let v123: f64 = v11 * v122;
        let v124: f64 = v119 + v123;
        let v125: f64 = v111 + v124;
        let v126: f64 = v110 * v125;
        let v127: f64 = v109 * v126;
        let v128: f64 = v108 + v127;
        let v129: f64 = v101 + v128;
        let v130: f64 = v6 + v129;
        let v131: f64 = v5 * v130;
        let v133: f64 = params[26];
        let v134: f64 = params[35];
        let v135: f64 = v30 * v28;
        let v136: f64 = v11 * v37;
        let v137: f64 = v135 + v136;
        let v138: f64 = v137 * v11;
        let v139: f64 = v30 * v44;
        let v140: f64 = v11 * v48;
        let v141: f64 = v139 + v140;
        let v142: f64 = v141 * v30;
        let v143: f64 = v138 - v142;
        let v144: f64 = v134 + v143;
        let v145: f64 = v144 * v8;
        let v146: f64 = params[38];
        let v147: f64 = v30 * v81;
        let v148: f64 = v11 * v86;
        let v149: f64 = v147 + v148;
        let v150: f64 = v146 - v149;
        let v151: f64 = v150 * v55;
        let v152: f64 = v145 + v151;
        let v153: f64 = params[31];
        let v154: f64 = v11 * v118;
        let v155: f64 = v30 * v122;
        let v156: f64 = v154 - v155;
        let v157: f64 = v153 + v156;
        let v158: f64 = v8 * v157;
        let v159: f64 = params[33];
        let v160: f64 = params[42];
        let v161: f64 = v17 * v113;
        let v162: f64 = v14 * v115;
        let v163: f64 = v161 + v162;
        let v164: f64 = v160 + v163;
        let v165: f64 = v159 - v164;
        let v166: f64 = v55 * v165;
        let v167: f64 = v158 + v166;
        let v168: f64 = v110 * v167;
        let v169: f64 = v152 - v168;
        let v170: f64 = v133 + v169;
        let v171: f64 = v132 * v170;
        let v172: f64 = v131 - v171;
        let v173: f64 = v172 * v5;
        let v174: f64 = v39 * v30;
        let v175: f64 = v50 * v11;
        let v176: f64 = v174 + v175;
        let v177: f64 = v134 + v176;
        let v178: f64 = v8 * v177;
        let v179: f64 = v71 * v30;
        let v180: f64 = v61 * v11;
        let v181: f64 = v179 + v180;
        let v182: f64 = v146 - v181;
        let v183: f64 = v55 * v182;
        let v184: f64 = v178 + v183;
        let v185: f64 = v184 - v168;
        let v186: f64 = v133 + v185;
        let v187: f64 = v5 * v186;
        let v188: f64 = params[29];
        let v189: f64 = params[37];
        let v190: f64 = v137 * v30;
        let v191: f64 = v141 * v11;
        (
            v0,
            v2,
            v3,
            v5,
            v8,
            v11,
            v30,
            v43,
            v47,
            v53,
            v55,
            v60,
            v74,
            v76,
            v82,
            v87,
            v89,
            v96,
            v97,
            v99,
            v107,
            v108,
            v109,
            v110,
            v117,
            v119,
            v123,
            v125,
            v126,
            v128,
            v130,
            v132,
            v144,
            v149,
            v150,
            v156,
            v157,
            v158,
            v161,
            v162,
            v165,
            v166,
            v167,
            v170,
            v172,
            v173,
            v177,
            v182,
            v184,
            v186,
            v187,
            v188,
            v189,
            v190,
            v191,
            v247,
        )
    };
    let (
        v193,
        v204,
        v205,
        v206,
        v208,
        v211,
        v215,
        v225,
        v229,
        v231,
        v232,
        v235,
        v238,
        v297,
        v298,
        v307,
        v329,
        v364,
        v374,
        v376,
        v378,
        v380,
        v382,
        v383,
    ) = {
        let v192: f64 = v190 + v191;
        let v193: f64 = v189 + v192;
        let v194: f64 = v193 + v128;
        let v195: f64 = v194 - v108;
        let v196: f64 = v195 - v126;
        let v197: f64 = v196 - v126;
        let v198: f64 = v188 + v197;
        let v199: f64 = v132 * v198;
        let v200: f64 = v187 - v199;
        let v201: f64 = v200 * v132;
        let v202: f64 = v173 - v201;
        let v203: f64 = params[20];
        let v204: f64 = v203 + v107;
        let v205: f64 = 0.0203_f64;
        let v206: f64 = v205 * v5;
        let v207: f64 = v206 * v206;
        let v208: f64 = v205 * v132;
        let v209: f64 = v208 * v208;
        let v210: f64 = v207 + v209;
        let v211: f64 = 0.022515002499999996_f64;
        let v212: f64 = v210 + v211;
        let v213: f64 = v204 * v212;
        let v214: f64 = params[21];
        let v215: f64 = v214 + v167;
        let v216: f64 = v5 * v215;
        let v217: f64 = params[23];
        let v218: f64 = v110 * v107;
        let v219: f64 = v125 + v218;
        let v220: f64 = v217 + v219;
        let v221: f64 = v132 * v220;
        let v222: f64 = v216 - v221;
        let v223: f64 = v222 * v206;
        let v224: f64 = v132 * v215;
        let v225: f64 = v5 * v220;
        let v226: f64 = v224 + v225;
        let v227: f64 = v226 * v208;
        let v228: f64 = v223 + v227;
        let v229: f64 = 0.15005_f64;
        let v230: f64 = params[22];
        let v231: f64 = v55 * v157;
        let v232: f64 = v8 * v165;
        let v233: f64 = v231 - v232;
        let v234: f64 = v230 + v233;
        let v235: f64 = v229 * v234;
        let v236: f64 = v228 - v235;
        let v237: f64 = v109 * v236;
        let v238: f64 = v213 + v237;
        let v239: f64 = v202 + v238;
        let v240: f64 = v204 * v207;
        let v241: f64 = v239 - v240;
        let v242: f64 = v241 - v223;
        let v243: f64 = v206 * v222;
        let v244: f64 = v242 - v243;
        let v245: f64 = v3 + v244;
        let v246: f64 = v2 * v245;
        let v248: f64 = params[15];
        let v249: f64 = v132 * v130;
        let v250: f64 = v5 * v170;
        let v251: f64 = v249 + v250;
        let v252: f64 = v251 * v5;
        let v253: f64 = v132 * v186;
        let v254: f64 = v5 * v198;
        let v255: f64 = v253 + v254;
        let v256: f64 = v255 * v132;
        let v257: f64 = v252 - v256;
        let v258: f64 = v208 * v206;
        let v259: f64 = v204 * v258;
        let v260: f64 = v257 - v259;
        let v261: f64 = v226 * v206;
        let v262: f64 = v260 - v261;
        let v263: f64 = v208 * v222;
        let v264: f64 = v262 - v263;
        let v265: f64 = v248 + v264;
        let v266: f64 = v247 * v265;
        let v267: f64 = v246 + v266;
        let v268: f64 = v267 * v2;
        let v269: f64 = v172 * v132;
        let v270: f64 = v200 * v5;
        let v271: f64 = v269 + v270;
        let v272: f64 = v206 * v208;
        let v273: f64 = v204 * v272;
        let v274: f64 = v271 - v273;
        let v275: f64 = v222 * v208;
        let v276: f64 = v274 - v275;
        let v277: f64 = v206 * v226;
        let v278: f64 = v276 - v277;
        let v279: f64 = v248 + v278;
        let v280: f64 = v2 * v279;
        let v281: f64 = params[17];
        let v282: f64 = v251 * v132;
        let v283: f64 = v255 * v5;
        let v284: f64 = v282 + v283;
        let v285: f64 = v284 + v238;
        let v286: f64 = v204 * v209;
        let v287: f64 = v285 - v286;
        let v288: f64 = v287 - v227;
        let v289: f64 = v208 * v226;
        let v290: f64 = v288 - v289;
        let v291: f64 = v281 + v290;
        let v292: f64 = v247 * v291;
        let v293: f64 = v280 + v292;
        let v294: f64 = v293 * v247;
        let v295: f64 = v268 + v294;
        let v296: f64 = params[10];
        let v297: f64 = v296 + v204;
        let v298: f64 = v110 * v247;
        let v299: f64 = v298 * v298;
        let v300: f64 = v110 * v2;
        let v301: f64 = v300 * v300;
        let v302: f64 = v299 + v301;
        let v303: f64 = v297 * v302;
        let v304: f64 = params[11];
        let v305: f64 = v204 * v206;
        let v306: f64 = v222 + v305;
        let v307: f64 = v304 + v306;
        let v308: f64 = v247 * v307;
        let v309: f64 = params[12];
        let v310: f64 = v204 * v208;
        let v311: f64 = v226 + v310;
        let v312: f64 = v309 + v311;
        let v313: f64 = v2 * v312;
        let v314: f64 = v308 - v313;
        let v315: f64 = v314 * v298;
        let v316: f64 = v2 * v307;
        let v317: f64 = v247 * v312;
        let v318: f64 = v316 + v317;
        let v319: f64 = v318 * v300;
        let v320: f64 = v315 + v319;
        let v321: f64 = v109 * v320;
        let v322: f64 = v303 + v321;
        let v323: f64 = v295 + v322;
        let v324: f64 = v297 * v301;
        let v325: f64 = v323 - v324;
        let v326: f64 = v325 - v319;
        let v327: f64 = v300 * v318;
        let v328: f64 = v326 - v327;
        let v329: f64 = v0 + v328;
        let v330: f64 = params[16];
        let v331: f64 = v206 * v234;
        let v332: f64 = params[25];
        let v333: f64 = v76 * v55;
        let v334: f64 = v99 * v8;
        let v335: f64 = v333 - v334;
        let v336: f64 = v332 + v335;
        let v337: f64 = v5 * v336;
        let v338: f64 = params[28];
        let v339: f64 = v144 * v55;
        let v340: f64 = v150 * v8;
        let v341: f64 = v339 - v340;
        let v342: f64 = v110 * v233;
        let v343: f64 = v341 - v342;
        let v344: f64 = v338 + v343;
        let v345: f64 = v132 * v344;
        let v346: f64 = v337 - v345;
        let v347: f64 = v229 * v206;
        let v348: f64 = v204 * v347;
        let v349: f64 = v346 + v348;
        let v350: f64 = v229 * v222;
        let v351: f64 = v349 + v350;
        let v352: f64 = v331 - v351;
        let v353: f64 = v330 + v352;
        let v354: f64 = params[13];
        let v355: f64 = v229 * v204;
        let v356: f64 = v355 - v234;
        let v357: f64 = v354 + v356;
        let v358: f64 = v110 * v357;
        let v359: f64 = v353 - v358;
        let v360: f64 = v2 * v359;
        let v361: f64 = params[18];
        let v362: f64 = v208 * v234;
        let v363: f64 = v132 * v336;
        let v364: f64 = v5 * v344;
        let v365: f64 = v363 + v364;
        let v366: f64 = v229 * v208;
        let v367: f64 = v204 * v366;
        let v368: f64 = v365 + v367;
        let v369: f64 = v229 * v226;
        let v370: f64 = v368 + v369;
        let v371: f64 = v362 - v370;
        let v372: f64 = v361 + v371;
        let v373: f64 = v247 * v372;
        let v374: f64 = v360 + v373;
        let v375: f64 = v205 * v234;
        let v376: f64 = v375 - v336;
        let v377: f64 = v5 * v376;
        let v378: f64 = v377 + v345;
        let v379: f64 = v205 * v204;
        let v380: f64 = v379 + v215;
        let v381: f64 = v5 * v380;
        let v382: f64 = v381 - v221;
        let v383: f64 = v229 * v382;
        (
            v193,
            v204,
            v205,
            v206,
            v208,
            v211,
            v215,
            v225,
            v229,
            v231,
            v232,
            v235,
            v238,
            v297,
            v298,
            v307,
            v329,
            v364,
            v374,
            v376,
            v378,
            v380,
            v382,
            v383,
        )
    };
    let (
        v393,
        v418,
        v452,
        v469,
        v497,
        v522,
        v530,
        v541,
        v552,
        v564,
        v566,
        v567,
        v569,
        v572,
        v573,
        v574,
    ) = {
        let v384: f64 = v378 - v383;
        let v385: f64 = v2 * v384;
        let v386: f64 = v132 * v376;
        let v387: f64 = v386 - v364;
        let v388: f64 = v132 * v380;
        let v389: f64 = v225 + v388;
        let v390: f64 = v229 * v389;
        let v391: f64 = v387 - v390;
        let v392: f64 = v247 * v391;
        let v393: f64 = v385 + v392;
        let v394: f64 = v166 + v158;
        let v395: f64 = v110 * v394;
        let v396: f64 = v184 - v395;
        let v397: f64 = v5 * v396;
        let v398: f64 = v132 * v193;
        let v399: f64 = v397 - v398;
        let v400: f64 = v208 * v394;
        let v401: f64 = v232 - v231;
        let v402: f64 = v132 * v401;
        let v403: f64 = v229 * v402;
        let v404: f64 = v400 + v403;
        let v405: f64 = v399 - v404;
        let v406: f64 = v2 * v405;
        let v407: f64 = v132 * v396;
        let v408: f64 = v5 * v193;
        let v409: f64 = v407 + v408;
        let v410: f64 = v5 * v401;
        let v411: f64 = v229 * v410;
        let v412: f64 = v206 * v394;
        let v413: f64 = v411 + v412;
        let v414: f64 = v409 + v413;
        let v415: f64 = v247 * v414;
        let v416: f64 = v406 + v415;
        let v417: f64 = v298 * v394;
        let v418: f64 = v416 + v417;
        let v419: f64 = v87 - v82;
        let v420: f64 = v8 * v419;
        let v421: f64 = v55 * v96;
        let v422: f64 = v420 + v421;
        let v423: f64 = v123 + v119;
        let v424: f64 = v55 * v423;
        let v425: f64 = v110 * v424;
        let v426: f64 = v422 + v425;
        let v427: f64 = v5 * v426;
        let v428: f64 = v132 * v149;
        let v429: f64 = v427 + v428;
        let v430: f64 = v208 * v424;
        let v431: f64 = v5 * v156;
        let v432: f64 = v8 * v423;
        let v433: f64 = v132 * v432;
        let v434: f64 = v431 - v433;
        let v435: f64 = v229 * v434;
        let v436: f64 = v430 - v435;
        let v437: f64 = v429 + v436;
        let v438: f64 = v2 * v437;
        let v439: f64 = v132 * v426;
        let v440: f64 = v5 * v149;
        let v441: f64 = v439 - v440;
        let v442: f64 = v5 * v432;
        let v443: f64 = v132 * v156;
        let v444: f64 = v442 + v443;
        let v445: f64 = v229 * v444;
        let v446: f64 = v206 * v424;
        let v447: f64 = v445 + v446;
        let v448: f64 = v441 - v447;
        let v449: f64 = v247 * v448;
        let v450: f64 = v438 + v449;
        let v451: f64 = v298 * v424;
        let v452: f64 = v450 - v451;
        let v453: f64 = v11 * v43;
        let v454: f64 = v30 * v47;
        let v455: f64 = v453 - v454;
        let v456: f64 = v8 * v455;
        let v457: f64 = v55 * v60;
        let v458: f64 = v456 - v457;
        let v459: f64 = v8 * v117;
        let v460: f64 = v162 + v161;
        let v461: f64 = v11 * v460;
        let v462: f64 = v55 * v461;
        let v463: f64 = v459 - v462;
        let v464: f64 = v110 * v463;
        let v465: f64 = v458 - v464;
        let v466: f64 = v5 * v465;
        let v467: f64 = v30 * v43;
        let v468: f64 = v11 * v47;
        let v469: f64 = v467 + v468;
        let v470: f64 = v132 * v469;
        let v471: f64 = v466 - v470;
        let v472: f64 = v8 * v461;
        let v473: f64 = v55 * v117;
        let v474: f64 = v472 + v473;
        let v475: f64 = v132 * v474;
        let v476: f64 = v30 * v460;
        let v477: f64 = v5 * v476;
        let v478: f64 = v475 + v477;
        let v479: f64 = v229 * v478;
        let v480: f64 = v208 * v463;
        let v481: f64 = v479 - v480;
        let v482: f64 = v471 + v481;
        let v483: f64 = v2 * v482;
        let v484: f64 = v132 * v465;
        let v485: f64 = v5 * v469;
        let v486: f64 = v484 + v485;
        let v487: f64 = v132 * v476;
        let v488: f64 = v5 * v474;
        let v489: f64 = v487 - v488;
        let v490: f64 = v229 * v489;
        let v491: f64 = v206 * v463;
        let v492: f64 = v490 + v491;
        let v493: f64 = v486 + v492;
        let v494: f64 = v247 * v493;
        let v495: f64 = v483 + v494;
        let v496: f64 = v298 * v463;
        let v497: f64 = v495 + v496;
        let v498: f64 = params[19];
        let v499: f64 = params[27];
        let v500: f64 = v55 * v53;
        let v501: f64 = v8 * v74;
        let v502: f64 = v500 - v501;
        let v503: f64 = v502 * v55;
        let v504: f64 = v55 * v89;
        let v505: f64 = v8 * v97;
        let v506: f64 = v504 - v505;
        let v507: f64 = v506 * v8;
        let v508: f64 = v503 - v507;
        let v509: f64 = v508 + v128;
        let v510: f64 = v499 + v509;
        let v511: f64 = v510 + v238;
        let v512: f64 = v211 * v204;
        let v513: f64 = v511 - v512;
        let v514: f64 = v513 + v235;
        let v515: f64 = v514 + v235;
        let v516: f64 = v498 + v515;
        let v517: f64 = v110 * v307;
        let v518: f64 = v516 + v517;
        let v519: f64 = v110 * v297;
        let v520: f64 = v519 + v307;
        let v521: f64 = v110 * v520;
        let v522: f64 = v518 + v521;
        let v523: f64 = v205 * v215;
        let v524: f64 = v510 + v523;
        let v525: f64 = v206 * v382;
        let v526: f64 = v208 * v389;
        let v527: f64 = v525 + v526;
        let v528: f64 = v524 + v527;
        let v529: f64 = v110 * v382;
        let v530: f64 = v528 + v529;
        let v531: f64 = v206 * v402;
        let v532: f64 = v208 * v410;
        let v533: f64 = v531 - v532;
        let v534: f64 = v55 * v177;
        let v535: f64 = v8 * v182;
        let v536: f64 = v534 - v535;
        let v537: f64 = v110 * v401;
        let v538: f64 = v536 + v537;
        let v539: f64 = v533 - v538;
        let v540: f64 = v110 * v402;
        let v541: f64 = v539 + v540;
        let v542: f64 = v206 * v434;
        let v543: f64 = v208 * v444;
        let v544: f64 = v542 + v543;
        let v545: f64 = v55 * v419;
        let v546: f64 = v8 * v96;
        let v547: f64 = v545 - v546;
        let v548: f64 = v110 * v432;
        let v549: f64 = v547 - v548;
        let v550: f64 = v544 - v549;
        let v551: f64 = v110 * v434;
        let v552: f64 = v550 + v551;
        let v553: f64 = v55 * v455;
        let v554: f64 = v8 * v60;
        let v555: f64 = v553 + v554;
        let v556: f64 = v110 * v474;
        let v557: f64 = v555 - v556;
        let v558: f64 = v206 * v478;
        let v559: f64 = v208 * v489;
        let v560: f64 = v558 + v559;
        let v561: f64 = v557 + v560;
        let v562: f64 = v110 * v478;
        let v563: f64 = v561 + v562;
        let v564: f64 = -v563;
        let v565: f64 = v205 * v380;
        let v566: f64 = v524 + v565;
        let v567: f64 = -v538;
        let v568: f64 = v205 * v156;
        let v569: f64 = v568 - v549;
        let v570: f64 = v205 * v476;
        let v571: f64 = v557 + v570;
        let v572: f64 = -v571;
        let v573: f64 = -v149;
        let v574: f64 = -v60;
        (
            v393,
            v418,
            v452,
            v469,
            v497,
            v522,
            v530,
            v541,
            v552,
            v564,
            v566,
            v567,
            v569,
            v572,
            v573,
            v574,
        )
    };
    [
        [v329, v374, v393, v418, v452, v497],
        [v374, v522, v530, v541, v552, v564],
        [v393, v530, v566, v567, v569, v572],
        [v418, v541, v567, v193, v573, v469],
        [v452, v552, v569, v573, v96, v574],
        [v497, v564, v572, v469, v574, v47],
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
/// Operation count: 4214 floating-point operations, 10 trig calls.
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
        v1,
        v3,
        v5,
        v6,
        v7,
        v9,
        v10,
        v11,
        v13,
        v15,
        v16,
        v18,
        v20,
        v22,
        v25,
        v26,
        v28,
        v29,
        v30,
        v31,
        v32,
        v33,
        v35,
        v38,
        v40,
        v41,
        v42,
        v44,
        v47,
        v48,
        v49,
        v52,
        v54,
        v58,
        v60,
        v65,
        v66,
        v68,
        v70,
        v72,
        v75,
        v78,
        v81,
        v87,
        v89,
        v91,
        v96,
        v97,
        v99,
        v101,
        v103,
        v106,
        v109,
        v112,
        v114,
        v117,
        v123,
        v126,
        v129,
        v136,
        v139,
        v142,
        v145,
        v148,
        v151,
        v159,
        v166,
        v169,
        v170,
        v173,
        v176,
        v180,
        v182,
        v183,
        v188,
        v189,
        v194,
    ) = {
        let v0: f64 = 0.5_f64;
        let v1: f64 = params[14];
        let v2: f64 = q[1];
        let (v3, v6): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
        let v4: f64 = v1 * v3;
        let v5: f64 = params[15];
        let v7: f64 = v5 * v6;
        let v8: f64 = v4 + v7;
        let v9: f64 = params[12];
        let v10: f64 = 0.4318_f64;
        let v11: f64 = v10 * v6;
        let v12: f64 = v9 * v11;
        let v13: f64 = v8 - v12;
        let v14: f64 = q[2];
        let (v18, v15): (f64, f64) = ::armdyn_runtime::libm::sincos(v14);
        let v16: f64 = params[24];
        let v17: f64 = v15 * v3;
        let v19: f64 = v18 * v6;
        let v20: f64 = v17 + v19;
        let v21: f64 = v16 * v20;
        let v22: f64 = params[26];
        let v23: f64 = v15 * v6;
        let v24: f64 = v18 * v3;
        let v25: f64 = v23 - v24;
        let v26: f64 = v22 * v25;
        let v27: f64 = v21 + v26;
        let v28: f64 = params[22];
        let v29: f64 = -0.15005_f64;
        let v30: f64 = v29 * v20;
        let v31: f64 = v28 * v30;
        let v32: f64 = params[23];
        let v33: f64 = 0.0203_f64;
        let v34: f64 = v33 * v25;
        let v35: f64 = v34 + v11;
        let v36: f64 = v32 * v35;
        let v37: f64 = v31 - v36;
        let v38: f64 = v27 + v37;
        let v39: f64 = q[3];
        let (v48, v40): (f64, f64) = ::armdyn_runtime::libm::sincos(v39);
        let v41: f64 = params[34];
        let v42: f64 = v40 * v20;
        let v43: f64 = v41 * v42;
        let v44: f64 = params[35];
        let v45: f64 = v44 * v25;
        let v46: f64 = v43 + v45;
        let v47: f64 = params[36];
        let v49: f64 = v48 * v20;
        let v50: f64 = v47 * v49;
        let v51: f64 = v46 + v50;
        let v52: f64 = params[32];
        let v53: f64 = v10 * v42;
        let v54: f64 = v29 * v25;
        let v55: f64 = v48 * v54;
        let v56: f64 = v40 * v35;
        let v57: f64 = v55 + v56;
        let v58: f64 = v53 - v57;
        let v59: f64 = v52 * v58;
        let v60: f64 = params[33];
        let v61: f64 = v60 * v30;
        let v62: f64 = v59 - v61;
        let v63: f64 = v51 + v62;
        let v64: f64 = q[4];
        let (v68, v65): (f64, f64) = ::armdyn_runtime::libm::sincos(v64);
        let v66: f64 = params[44];
        let v67: f64 = v65 * v42;
        let v69: f64 = v68 * v25;
        let v70: f64 = v67 + v69;
        let v71: f64 = v66 * v70;
        let v72: f64 = params[45];
        let v73: f64 = v72 * v49;
        let v74: f64 = v71 - v73;
        let v75: f64 = params[46];
        let v76: f64 = v65 * v25;
        let v77: f64 = v68 * v42;
        let v78: f64 = v76 - v77;
        let v79: f64 = v75 * v78;
        let v80: f64 = v74 + v79;
        let v81: f64 = params[42];
        let v82: f64 = v65 * v30;
        let v83: f64 = v48 * v35;
        let v84: f64 = v40 * v54;
        let v85: f64 = v83 - v84;
        let v86: f64 = v10 * v49;
        let v87: f64 = v85 - v86;
        let v88: f64 = v68 * v87;
        let v89: f64 = v82 - v88;
        let v90: f64 = v81 * v89;
        let v91: f64 = params[43];
        let v92: f64 = v91 * v58;
        let v93: f64 = v90 + v92;
        let v94: f64 = v80 + v93;
        let v95: f64 = q[5];
        let (v99, v96): (f64, f64) = ::armdyn_runtime::libm::sincos(v95);
        let v97: f64 = params[54];
        let v98: f64 = v96 * v70;
        let v100: f64 = v99 * v49;
        let v101: f64 = v98 - v100;
        let v102: f64 = v97 * v101;
        let v103: f64 = params[55];
        let v104: f64 = v99 * v70;
        let v105: f64 = v96 * v49;
        let v106: f64 = v104 + v105;
        let v107: f64 = v103 * v106;
        let v108: f64 = v102 - v107;
        let v109: f64 = params[56];
        let v110: f64 = v109 * v78;
        let v111: f64 = v108 + v110;
        let v112: f64 = params[52];
        let v113: f64 = v112 * v89;
        let v114: f64 = params[53];
        let v115: f64 = v65 * v87;
        let v116: f64 = v68 * v30;
        let v117: f64 = v115 + v116;
        let v118: f64 = v99 * v117;
        let v119: f64 = v96 * v58;
        let v120: f64 = v118 + v119;
        let v121: f64 = v114 * v120;
        let v122: f64 = v113 + v121;
        let v123: f64 = v111 + v122;
        let v124: f64 = v96 * v123;
        let v125: f64 = v103 * v101;
        let v126: f64 = params[57];
        let v127: f64 = v126 * v106;
        let v128: f64 = v125 - v127;
        let v129: f64 = params[58];
        let v130: f64 = v129 * v78;
        let v131: f64 = v128 + v130;
        let v132: f64 = v96 * v117;
        let v133: f64 = v99 * v58;
        let v134: f64 = v132 - v133;
        let v135: f64 = v114 * v134;
        let v136: f64 = params[51];
        let v137: f64 = v136 * v89;
        let v138: f64 = v135 - v137;
        let v139: f64 = v131 + v138;
        let v140: f64 = v99 * v139;
        let v141: f64 = v124 - v140;
        let v142: f64 = v94 + v141;
        let v143: f64 = v65 * v142;
        let v144: f64 = v75 * v70;
        let v145: f64 = params[48];
        let v146: f64 = v145 * v49;
        let v147: f64 = v144 - v146;
        let v148: f64 = params[49];
        let v149: f64 = v148 * v78;
        let v150: f64 = v147 + v149;
        let v151: f64 = params[41];
        let v152: f64 = v151 * v58;
        let v153: f64 = v81 * v117;
        let v154: f64 = v152 + v153;
        let v155: f64 = v150 - v154;
        let v156: f64 = v109 * v101;
        let v157: f64 = v129 * v106;
        let v158: f64 = v156 - v157;
        let v159: f64 = params[59];
        let v160: f64 = v159 * v78;
        let v161: f64 = v158 + v160;
        let v162: f64 = v136 * v120;
        let v163: f64 = v112 * v134;
        let v164: f64 = v162 + v163;
        let v165: f64 = v161 - v164;
        let v166: f64 = v155 + v165;
        let v167: f64 = v68 * v166;
        let v168: f64 = v143 - v167;
        let v169: f64 = v63 + v168;
        let v170: f64 = params[30];
        let v171: f64 = v170 * v58;
        let v172: f64 = v52 * v42;
        let v173: f64 = params[31];
        let v174: f64 = v173 * v25;
        let v175: f64 = v172 - v174;
        let v176: f64 = v171 + v175;
        let v177: f64 = v151 * v78;
        let v178: f64 = v91 * v70;
        let v179: f64 = v177 - v178;
        let v180: f64 = params[40];
        let v181: f64 = v180 * v58;
        let v182: f64 = v179 - v181;
        let v183: f64 = params[50];
        let v184: f64 = v183 * v134;
        let v185: f64 = v114 * v106;
        let v186: f64 = v112 * v78;
        let v187: f64 = v185 + v186;
        let v188: f64 = v184 - v187;
        let v189: f64 = v99 * v188;
        let v190: f64 = v136 * v78;
        let v191: f64 = v114 * v101;
        let v192: f64 = v190 - v191;
        let v193: f64 = v183 * v120;
        let v194: f64 = v192 - v193;
        (
            v0,
            v1,
            v3,
            v5,
            v6,
            v7,
            v9,
            v10,
            v11,
            v13,
            v15,
            v16,
            v18,
            v20,
            v22,
            v25,
            v26,
            v28,
            v29,
            v30,
            v31,
            v32,
            v33,
            v35,
            v38,
            v40,
            v41,
            v42,
            v44,
            v47,
            v48,
            v49,
            v52,
            v54,
            v58,
            v60,
            v65,
            v66,
            v68,
            v70,
            v72,
            v75,
            v78,
            v81,
            v87,
            v89,
            v91,
            v96,
            v97,
            v99,
            v101,
            v103,
            v106,
            v109,
            v112,
            v114,
            v117,
            v123,
            v126,
            v129,
            v136,
            v139,
            v142,
            v145,
            v148,
            v151,
            v159,
            v166,
            v169,
            v170,
            v173,
            v176,
            v180,
            v182,
            v183,
            v188,
            v189,
            v194,
        )
    };
    let (
        v198,
        v200,
        v203,
        v206,
        v214,
        v241,
        v253,
        v256,
        v258,
        v262,
        v265,
        v275,
        v277,
        v280,
        v283,
        v289,
        v311,
        v318,
        v319,
        v322,
        v326,
        v328,
        v330,
        v332,
        v336,
        v339,
        v340,
        v344,
        v351,
        v355,
        v358,
        v364,
        v372,
        v374,
        v378,
        v381,
        v385,
        v389,
    ) = {
        let v195: f64 = v96 * v194;
        let v196: f64 = v189 + v195;
        let v197: f64 = v182 + v196;
        let v198: f64 = v176 - v197;
        let v199: f64 = v10 * v198;
        let v200: f64 = v169 + v199;
        let v201: f64 = v40 * v200;
        let v202: f64 = v47 * v42;
        let v203: f64 = params[38];
        let v204: f64 = v203 * v25;
        let v205: f64 = v202 + v204;
        let v206: f64 = params[39];
        let v207: f64 = v206 * v49;
        let v208: f64 = v205 + v207;
        let v209: f64 = v173 * v30;
        let v210: f64 = v52 * v87;
        let v211: f64 = v209 - v210;
        let v212: f64 = v208 + v211;
        let v213: f64 = v72 * v70;
        let v214: f64 = params[47];
        let v215: f64 = v214 * v49;
        let v216: f64 = v213 - v215;
        let v217: f64 = v145 * v78;
        let v218: f64 = v216 + v217;
        let v219: f64 = v91 * v117;
        let v220: f64 = v151 * v89;
        let v221: f64 = v219 - v220;
        let v222: f64 = v218 + v221;
        let v223: f64 = v99 * v123;
        let v224: f64 = v96 * v139;
        let v225: f64 = v223 + v224;
        let v226: f64 = v222 + v225;
        let v227: f64 = v212 - v226;
        let v228: f64 = v170 * v87;
        let v229: f64 = v60 * v25;
        let v230: f64 = v52 * v49;
        let v231: f64 = v229 - v230;
        let v232: f64 = v228 + v231;
        let v233: f64 = v180 * v117;
        let v234: f64 = v91 * v49;
        let v235: f64 = v81 * v78;
        let v236: f64 = v234 + v235;
        let v237: f64 = v233 - v236;
        let v238: f64 = v96 * v188;
        let v239: f64 = v99 * v194;
        let v240: f64 = v238 - v239;
        let v241: f64 = v237 + v240;
        let v242: f64 = v65 * v241;
        let v243: f64 = v180 * v89;
        let v244: f64 = v81 * v70;
        let v245: f64 = v151 * v49;
        let v246: f64 = v244 + v245;
        let v247: f64 = v243 + v246;
        let v248: f64 = v183 * v89;
        let v249: f64 = v112 * v101;
        let v250: f64 = v136 * v106;
        let v251: f64 = v249 + v250;
        let v252: f64 = v248 + v251;
        let v253: f64 = v247 + v252;
        let v254: f64 = v68 * v253;
        let v255: f64 = v242 - v254;
        let v256: f64 = v232 + v255;
        let v257: f64 = v10 * v256;
        let v258: f64 = v227 - v257;
        let v259: f64 = v48 * v258;
        let v260: f64 = v201 + v259;
        let v261: f64 = v38 + v260;
        let v262: f64 = params[20];
        let v263: f64 = v262 * v30;
        let v264: f64 = v28 * v20;
        let v265: f64 = v263 + v264;
        let v266: f64 = v170 * v30;
        let v267: f64 = v173 * v49;
        let v268: f64 = v60 * v42;
        let v269: f64 = v267 - v268;
        let v270: f64 = v266 + v269;
        let v271: f64 = v68 * v241;
        let v272: f64 = v65 * v253;
        let v273: f64 = v271 + v272;
        let v274: f64 = v270 + v273;
        let v275: f64 = v265 + v274;
        let v276: f64 = v29 * v275;
        let v277: f64 = v261 + v276;
        let v278: f64 = v15 * v277;
        let v279: f64 = v22 * v20;
        let v280: f64 = params[29];
        let v281: f64 = v280 * v25;
        let v282: f64 = v279 + v281;
        let v283: f64 = params[21];
        let v284: f64 = v283 * v35;
        let v285: f64 = v28 * v54;
        let v286: f64 = v284 + v285;
        let v287: f64 = v282 + v286;
        let v288: f64 = v44 * v42;
        let v289: f64 = params[37];
        let v290: f64 = v289 * v25;
        let v291: f64 = v288 + v290;
        let v292: f64 = v203 * v49;
        let v293: f64 = v291 + v292;
        let v294: f64 = v60 * v87;
        let v295: f64 = v173 * v58;
        let v296: f64 = v294 - v295;
        let v297: f64 = v293 + v296;
        let v298: f64 = v68 * v142;
        let v299: f64 = v65 * v166;
        let v300: f64 = v298 + v299;
        let v301: f64 = v297 + v300;
        let v302: f64 = v287 + v301;
        let v303: f64 = v262 * v35;
        let v304: f64 = v283 * v25;
        let v305: f64 = v32 * v20;
        let v306: f64 = v304 - v305;
        let v307: f64 = v303 + v306;
        let v308: f64 = v48 * v256;
        let v309: f64 = v40 * v198;
        let v310: f64 = v308 - v309;
        let v311: f64 = v307 + v310;
        let v312: f64 = v33 * v311;
        let v313: f64 = v40 * v256;
        let v314: f64 = v48 * v198;
        let v315: f64 = v313 + v314;
        let v316: f64 = v262 * v54;
        let v317: f64 = v28 * v25;
        let v318: f64 = v316 + v317;
        let v319: f64 = v315 - v318;
        let v320: f64 = v29 * v319;
        let v321: f64 = v312 - v320;
        let v322: f64 = v302 + v321;
        let v323: f64 = v18 * v322;
        let v324: f64 = v278 - v323;
        let v325: f64 = v13 + v324;
        let v326: f64 = v325 * v6;
        let v327: f64 = v1 * v6;
        let v328: f64 = v5 * v3;
        let v329: f64 = v327 - v328;
        let v330: f64 = v10 * v3;
        let v331: f64 = v9 * v330;
        let v332: f64 = v329 + v331;
        let v333: f64 = v16 * v25;
        let v334: f64 = v333 - v279;
        let v335: f64 = v33 * v20;
        let v336: f64 = v335 + v330;
        let v337: f64 = v32 * v336;
        let v338: f64 = v285 + v337;
        let v339: f64 = v334 + v338;
        let v340: f64 = v40 * v25;
        let v341: f64 = v41 * v340;
        let v342: f64 = v44 * v20;
        let v343: f64 = v341 - v342;
        let v344: f64 = v48 * v25;
        let v345: f64 = v47 * v344;
        let v346: f64 = v343 + v345;
        let v347: f64 = v10 * v340;
        let v348: f64 = v48 * v30;
        let v349: f64 = v40 * v336;
        let v350: f64 = v348 + v349;
        let v351: f64 = v347 + v350;
        let v352: f64 = v52 * v351;
        let v353: f64 = v60 * v54;
        let v354: f64 = v352 - v353;
        let v355: f64 = v346 + v354;
        let v356: f64 = v65 * v340;
        let v357: f64 = v68 * v20;
        let v358: f64 = v356 - v357;
        let v359: f64 = v66 * v358;
        let v360: f64 = v72 * v344;
        let v361: f64 = v359 - v360;
        let v362: f64 = v65 * v20;
        let v363: f64 = v68 * v340;
        let v364: f64 = v362 + v363;
        let v365: f64 = v75 * v364;
        let v366: f64 = v361 - v365;
        let v367: f64 = v65 * v54;
        let v368: f64 = v40 * v30;
        let v369: f64 = v48 * v336;
        let v370: f64 = v368 - v369;
        let v371: f64 = v10 * v344;
        let v372: f64 = v370 - v371;
        let v373: f64 = v68 * v372;
        let v374: f64 = v367 - v373;
        let v375: f64 = v81 * v374;
        let v376: f64 = v91 * v351;
        let v377: f64 = v375 + v376;
        let v378: f64 = v366 + v377;
        let v379: f64 = v96 * v358;
        let v380: f64 = v99 * v344;
        let v381: f64 = v379 - v380;
        let v382: f64 = v97 * v381;
        let v383: f64 = v99 * v358;
        let v384: f64 = v96 * v344;
        let v385: f64 = v383 + v384;
        let v386: f64 = v103 * v385;
        let v387: f64 = v382 - v386;
        let v388: f64 = v109 * v364;
        let v389: f64 = v387 - v388;
        (
            v198,
            v200,
            v203,
            v206,
            v214,
            v241,
            v253,
            v256,
            v258,
            v262,
            v265,
            v275,
            v277,
            v280,
            v283,
            v289,
            v311,
            v318,
            v319,
            v322,
            v326,
            v328,
            v330,
            v332,
            v336,
            v339,
            v340,
            v344,
            v351,
            v355,
            v358,
            v364,
            v372,
            v374,
            v378,
            v381,
            v385,
            v389,
        )
    };
    let (
        v434,
        v465,
        v488,
        v520,
        v533,
        v554,
        v564,
        v569,
        v572,
        v577,
        v578,
        v581,
        v583,
        v584,
    ) = {
        let v390: f64 = v112 * v374;
        let v391: f64 = v65 * v372;
        let v392: f64 = v68 * v54;
        let v393: f64 = v391 + v392;
        let v394: f64 = v99 * v393;
        let v395: f64 = v96 * v351;
        let v396: f64 = v394 + v395;
        let v397: f64 = v114 * v396;
        let v398: f64 = v390 + v397;
        let v399: f64 = v389 + v398;
        let v400: f64 = v96 * v399;
        let v401: f64 = v103 * v381;
        let v402: f64 = v126 * v385;
        let v403: f64 = v401 - v402;
        let v404: f64 = v129 * v364;
        let v405: f64 = v403 - v404;
        let v406: f64 = v96 * v393;
        let v407: f64 = v99 * v351;
        let v408: f64 = v406 - v407;
        let v409: f64 = v114 * v408;
        let v410: f64 = v136 * v374;
        let v411: f64 = v409 - v410;
        let v412: f64 = v405 + v411;
        let v413: f64 = v99 * v412;
        let v414: f64 = v400 - v413;
        let v415: f64 = v378 + v414;
        let v416: f64 = v65 * v415;
        let v417: f64 = v75 * v358;
        let v418: f64 = v145 * v344;
        let v419: f64 = v417 - v418;
        let v420: f64 = v148 * v364;
        let v421: f64 = v419 - v420;
        let v422: f64 = v151 * v351;
        let v423: f64 = v81 * v393;
        let v424: f64 = v422 + v423;
        let v425: f64 = v421 - v424;
        let v426: f64 = v109 * v381;
        let v427: f64 = v129 * v385;
        let v428: f64 = v426 - v427;
        let v429: f64 = v159 * v364;
        let v430: f64 = v428 - v429;
        let v431: f64 = v136 * v396;
        let v432: f64 = v112 * v408;
        let v433: f64 = v431 + v432;
        let v434: f64 = v430 - v433;
        let v435: f64 = v425 + v434;
        let v436: f64 = v68 * v435;
        let v437: f64 = v416 - v436;
        let v438: f64 = v355 + v437;
        let v439: f64 = v170 * v351;
        let v440: f64 = v52 * v340;
        let v441: f64 = v173 * v20;
        let v442: f64 = v440 + v441;
        let v443: f64 = v439 + v442;
        let v444: f64 = v183 * v408;
        let v445: f64 = v114 * v385;
        let v446: f64 = v112 * v364;
        let v447: f64 = v445 - v446;
        let v448: f64 = v444 - v447;
        let v449: f64 = v99 * v448;
        let v450: f64 = v136 * v364;
        let v451: f64 = v114 * v381;
        let v452: f64 = v450 + v451;
        let v453: f64 = v183 * v396;
        let v454: f64 = v452 + v453;
        let v455: f64 = v96 * v454;
        let v456: f64 = v449 - v455;
        let v457: f64 = v151 * v364;
        let v458: f64 = v91 * v358;
        let v459: f64 = v457 + v458;
        let v460: f64 = v180 * v351;
        let v461: f64 = v459 + v460;
        let v462: f64 = v456 - v461;
        let v463: f64 = v443 - v462;
        let v464: f64 = v10 * v463;
        let v465: f64 = v438 + v464;
        let v466: f64 = v40 * v465;
        let v467: f64 = v47 * v340;
        let v468: f64 = v203 * v20;
        let v469: f64 = v467 - v468;
        let v470: f64 = v206 * v344;
        let v471: f64 = v469 + v470;
        let v472: f64 = v173 * v54;
        let v473: f64 = v52 * v372;
        let v474: f64 = v472 - v473;
        let v475: f64 = v471 + v474;
        let v476: f64 = v72 * v358;
        let v477: f64 = v214 * v344;
        let v478: f64 = v476 - v477;
        let v479: f64 = v145 * v364;
        let v480: f64 = v478 - v479;
        let v481: f64 = v91 * v393;
        let v482: f64 = v151 * v374;
        let v483: f64 = v481 - v482;
        let v484: f64 = v480 + v483;
        let v485: f64 = v99 * v399;
        let v486: f64 = v96 * v412;
        let v487: f64 = v485 + v486;
        let v488: f64 = v484 + v487;
        let v489: f64 = v475 - v488;
        let v490: f64 = v170 * v372;
        let v491: f64 = v60 * v20;
        let v492: f64 = v52 * v344;
        let v493: f64 = v491 + v492;
        let v494: f64 = v490 - v493;
        let v495: f64 = v180 * v393;
        let v496: f64 = v91 * v344;
        let v497: f64 = v81 * v364;
        let v498: f64 = v496 - v497;
        let v499: f64 = v495 - v498;
        let v500: f64 = v96 * v448;
        let v501: f64 = v99 * v454;
        let v502: f64 = v500 + v501;
        let v503: f64 = v499 + v502;
        let v504: f64 = v65 * v503;
        let v505: f64 = v180 * v374;
        let v506: f64 = v81 * v358;
        let v507: f64 = v151 * v344;
        let v508: f64 = v506 + v507;
        let v509: f64 = v505 + v508;
        let v510: f64 = v183 * v374;
        let v511: f64 = v112 * v381;
        let v512: f64 = v136 * v385;
        let v513: f64 = v511 + v512;
        let v514: f64 = v510 + v513;
        let v515: f64 = v509 + v514;
        let v516: f64 = v68 * v515;
        let v517: f64 = v504 - v516;
        let v518: f64 = v494 + v517;
        let v519: f64 = v10 * v518;
        let v520: f64 = v489 - v519;
        let v521: f64 = v48 * v520;
        let v522: f64 = v466 + v521;
        let v523: f64 = v339 + v522;
        let v524: f64 = v170 * v54;
        let v525: f64 = v173 * v344;
        let v526: f64 = v60 * v340;
        let v527: f64 = v525 - v526;
        let v528: f64 = v524 + v527;
        let v529: f64 = v68 * v503;
        let v530: f64 = v65 * v515;
        let v531: f64 = v529 + v530;
        let v532: f64 = v528 + v531;
        let v533: f64 = v318 + v532;
        let v534: f64 = v29 * v533;
        let v535: f64 = v523 + v534;
        let v536: f64 = v15 * v535;
        let v537: f64 = v280 * v20;
        let v538: f64 = v26 - v537;
        let v539: f64 = v283 * v336;
        let v540: f64 = v539 + v31;
        let v541: f64 = v538 - v540;
        let v542: f64 = v44 * v340;
        let v543: f64 = v289 * v20;
        let v544: f64 = v542 - v543;
        let v545: f64 = v203 * v344;
        let v546: f64 = v544 + v545;
        let v547: f64 = v60 * v372;
        let v548: f64 = v173 * v351;
        let v549: f64 = v547 - v548;
        let v550: f64 = v546 + v549;
        let v551: f64 = v68 * v415;
        let v552: f64 = v65 * v435;
        let v553: f64 = v551 + v552;
        let v554: f64 = v550 + v553;
        let v555: f64 = v541 + v554;
        let v556: f64 = v48 * v518;
        let v557: f64 = v40 * v463;
        let v558: f64 = v556 - v557;
        let v559: f64 = v262 * v336;
        let v560: f64 = v283 * v20;
        let v561: f64 = v32 * v25;
        let v562: f64 = v560 + v561;
        let v563: f64 = v559 + v562;
        let v564: f64 = v558 - v563;
        let v565: f64 = v33 * v564;
        let v566: f64 = v40 * v518;
        let v567: f64 = v48 * v463;
        let v568: f64 = v566 + v567;
        let v569: f64 = v568 + v265;
        let v570: f64 = v29 * v569;
        let v571: f64 = v565 - v570;
        let v572: f64 = v555 + v571;
        let v573: f64 = v18 * v572;
        let v574: f64 = v536 - v573;
        let v575: f64 = v332 + v574;
        let v576: f64 = v3 * v575;
        let v577: f64 = v326 + v576;
        let v578: f64 = params[17];
        let v579: f64 = v578 * v3;
        let v580: f64 = v7 - v579;
        let v581: f64 = params[11];
        let v582: f64 = v581 * v330;
        let v583: f64 = v580 - v582;
        let v584: f64 = v18 * v535;
        (
            v434,
            v465,
            v488,
            v520,
            v533,
            v554,
            v564,
            v569,
            v572,
            v577,
            v578,
            v581,
            v583,
            v584,
        )
    };
    let (
        v617,
        v618,
        v619,
        v622,
        v626,
        v629,
        v631,
        v634,
        v635,
        v639,
        v643,
        v647,
        v654,
        v660,
        v668,
        v670,
        v677,
        v681,
        v689,
        v695,
        v708,
        v711,
        v730,
        v731,
        v744,
        v750,
        v759,
        v761,
        v762,
        v771,
        v776,
        v779,
    ) = {
        let v585: f64 = v15 * v572;
        let v586: f64 = v584 + v585;
        let v587: f64 = v583 + v586;
        let v588: f64 = v9 * v6;
        let v589: f64 = v581 * v3;
        let v590: f64 = v588 + v589;
        let v591: f64 = params[10];
        let v592: f64 = v591 * v330;
        let v593: f64 = v590 + v592;
        let v594: f64 = v593 - v564;
        let v595: f64 = v10 * v594;
        let v596: f64 = v587 - v595;
        let v597: f64 = v6 * v596;
        let v598: f64 = v578 * v6;
        let v599: f64 = v328 + v598;
        let v600: f64 = v581 * v11;
        let v601: f64 = v599 + v600;
        let v602: f64 = v18 * v277;
        let v603: f64 = v15 * v322;
        let v604: f64 = v602 + v603;
        let v605: f64 = v601 + v604;
        let v606: f64 = v9 * v3;
        let v607: f64 = v581 * v6;
        let v608: f64 = v606 - v607;
        let v609: f64 = v591 * v11;
        let v610: f64 = v608 - v609;
        let v611: f64 = v610 - v311;
        let v612: f64 = v10 * v611;
        let v613: f64 = v605 - v612;
        let v614: f64 = v613 * v3;
        let v615: f64 = v597 - v614;
        let v616: f64 = v577 + v615;
        let v617: f64 = v0 * v616;
        let v618: f64 = qd[1];
        let v619: f64 = v617 * v618;
        let v620: f64 = v6 * v15;
        let v621: f64 = v3 * v18;
        let v622: f64 = v620 - v621;
        let v623: f64 = v16 * v622;
        let v624: f64 = v6 * v18;
        let v625: f64 = v3 * v15;
        let v626: f64 = v624 + v625;
        let v627: f64 = v22 * v626;
        let v628: f64 = v623 - v627;
        let v629: f64 = v29 * v622;
        let v630: f64 = v28 * v629;
        let v631: f64 = v33 * v626;
        let v632: f64 = v32 * v631;
        let v633: f64 = v630 + v632;
        let v634: f64 = v628 + v633;
        let v635: f64 = v40 * v622;
        let v636: f64 = v41 * v635;
        let v637: f64 = v44 * v626;
        let v638: f64 = v636 - v637;
        let v639: f64 = v48 * v622;
        let v640: f64 = v47 * v639;
        let v641: f64 = v638 + v640;
        let v642: f64 = v10 * v635;
        let v643: f64 = v29 * v626;
        let v644: f64 = v48 * v643;
        let v645: f64 = v40 * v631;
        let v646: f64 = v644 + v645;
        let v647: f64 = v642 + v646;
        let v648: f64 = v52 * v647;
        let v649: f64 = v60 * v629;
        let v650: f64 = v648 - v649;
        let v651: f64 = v641 + v650;
        let v652: f64 = v65 * v635;
        let v653: f64 = v68 * v626;
        let v654: f64 = v652 - v653;
        let v655: f64 = v66 * v654;
        let v656: f64 = v72 * v639;
        let v657: f64 = v655 - v656;
        let v658: f64 = v65 * v626;
        let v659: f64 = v68 * v635;
        let v660: f64 = v658 + v659;
        let v661: f64 = v75 * v660;
        let v662: f64 = v657 - v661;
        let v663: f64 = v65 * v629;
        let v664: f64 = v40 * v643;
        let v665: f64 = v48 * v631;
        let v666: f64 = v664 - v665;
        let v667: f64 = v10 * v639;
        let v668: f64 = v666 - v667;
        let v669: f64 = v68 * v668;
        let v670: f64 = v663 - v669;
        let v671: f64 = v81 * v670;
        let v672: f64 = v91 * v647;
        let v673: f64 = v671 + v672;
        let v674: f64 = v662 + v673;
        let v675: f64 = v96 * v654;
        let v676: f64 = v99 * v639;
        let v677: f64 = v675 - v676;
        let v678: f64 = v97 * v677;
        let v679: f64 = v99 * v654;
        let v680: f64 = v96 * v639;
        let v681: f64 = v679 + v680;
        let v682: f64 = v103 * v681;
        let v683: f64 = v678 - v682;
        let v684: f64 = v109 * v660;
        let v685: f64 = v683 - v684;
        let v686: f64 = v112 * v670;
        let v687: f64 = v65 * v668;
        let v688: f64 = v68 * v629;
        let v689: f64 = v687 + v688;
        let v690: f64 = v99 * v689;
        let v691: f64 = v96 * v647;
        let v692: f64 = v690 + v691;
        let v693: f64 = v114 * v692;
        let v694: f64 = v686 + v693;
        let v695: f64 = v685 + v694;
        let v696: f64 = v96 * v695;
        let v697: f64 = v103 * v677;
        let v698: f64 = v126 * v681;
        let v699: f64 = v697 - v698;
        let v700: f64 = v129 * v660;
        let v701: f64 = v699 - v700;
        let v702: f64 = v96 * v689;
        let v703: f64 = v99 * v647;
        let v704: f64 = v702 - v703;
        let v705: f64 = v114 * v704;
        let v706: f64 = v136 * v670;
        let v707: f64 = v705 - v706;
        let v708: f64 = v701 + v707;
        let v709: f64 = v99 * v708;
        let v710: f64 = v696 - v709;
        let v711: f64 = v674 + v710;
        let v712: f64 = v65 * v711;
        let v713: f64 = v75 * v654;
        let v714: f64 = v145 * v639;
        let v715: f64 = v713 - v714;
        let v716: f64 = v148 * v660;
        let v717: f64 = v715 - v716;
        let v718: f64 = v151 * v647;
        let v719: f64 = v81 * v689;
        let v720: f64 = v718 + v719;
        let v721: f64 = v717 - v720;
        let v722: f64 = v109 * v677;
        let v723: f64 = v129 * v681;
        let v724: f64 = v722 - v723;
        let v725: f64 = v159 * v660;
        let v726: f64 = v724 - v725;
        let v727: f64 = v136 * v692;
        let v728: f64 = v112 * v704;
        let v729: f64 = v727 + v728;
        let v730: f64 = v726 - v729;
        let v731: f64 = v721 + v730;
        let v732: f64 = v68 * v731;
        let v733: f64 = v712 - v732;
        let v734: f64 = v651 + v733;
        let v735: f64 = v170 * v647;
        let v736: f64 = v52 * v635;
        let v737: f64 = v173 * v626;
        let v738: f64 = v736 + v737;
        let v739: f64 = v735 + v738;
        let v740: f64 = v183 * v704;
        let v741: f64 = v114 * v681;
        let v742: f64 = v112 * v660;
        let v743: f64 = v741 - v742;
        let v744: f64 = v740 - v743;
        let v745: f64 = v99 * v744;
        let v746: f64 = v136 * v660;
        let v747: f64 = v114 * v677;
        let v748: f64 = v746 + v747;
        let v749: f64 = v183 * v692;
        let v750: f64 = v748 + v749;
        let v751: f64 = v96 * v750;
        let v752: f64 = v745 - v751;
        let v753: f64 = v151 * v660;
        let v754: f64 = v91 * v654;
        let v755: f64 = v753 + v754;
        let v756: f64 = v180 * v647;
        let v757: f64 = v755 + v756;
        let v758: f64 = v752 - v757;
        let v759: f64 = v739 - v758;
        let v760: f64 = v10 * v759;
        let v761: f64 = v734 + v760;
        let v762: f64 = v40 * v761;
        let v763: f64 = v47 * v635;
        let v764: f64 = v203 * v626;
        let v765: f64 = v763 - v764;
        let v766: f64 = v206 * v639;
        let v767: f64 = v765 + v766;
        let v768: f64 = v173 * v629;
        let v769: f64 = v52 * v668;
        let v770: f64 = v768 - v769;
        let v771: f64 = v767 + v770;
        let v772: f64 = v72 * v654;
        let v773: f64 = v214 * v639;
        let v774: f64 = v772 - v773;
        let v775: f64 = v145 * v660;
        let v776: f64 = v774 - v775;
        let v777: f64 = v91 * v689;
        let v778: f64 = v151 * v670;
        let v779: f64 = v777 - v778;
        (
            v617,
            v618,
            v619,
            v622,
            v626,
            v629,
            v631,
            v634,
            v635,
            v639,
            v643,
            v647,
            v654,
            v660,
            v668,
            v670,
            v677,
            v681,
            v689,
            v695,
            v708,
            v711,
            v730,
            v731,
            v744,
            v750,
            v759,
            v761,
            v762,
            v771,
            v776,
            v779,
        )
    };
    let (
        v784,
        v816,
        v832,
        v858,
        v876,
        v895,
        v896,
        v898,
        v899,
        v901,
        v908,
        v910,
        v911,
        v913,
        v922,
        v923,
        v931,
        v935,
        v939,
        v942,
        v946,
        v955,
        v959,
        v962,
        v963,
        v972,
        v973,
        v974,
    ) = {
        let v780: f64 = v776 + v779;
        let v781: f64 = v99 * v695;
        let v782: f64 = v96 * v708;
        let v783: f64 = v781 + v782;
        let v784: f64 = v780 + v783;
        let v785: f64 = v771 - v784;
        let v786: f64 = v170 * v668;
        let v787: f64 = v60 * v626;
        let v788: f64 = v52 * v639;
        let v789: f64 = v787 + v788;
        let v790: f64 = v786 - v789;
        let v791: f64 = v180 * v689;
        let v792: f64 = v91 * v639;
        let v793: f64 = v81 * v660;
        let v794: f64 = v792 - v793;
        let v795: f64 = v791 - v794;
        let v796: f64 = v96 * v744;
        let v797: f64 = v99 * v750;
        let v798: f64 = v796 + v797;
        let v799: f64 = v795 + v798;
        let v800: f64 = v65 * v799;
        let v801: f64 = v180 * v670;
        let v802: f64 = v81 * v654;
        let v803: f64 = v151 * v639;
        let v804: f64 = v802 + v803;
        let v805: f64 = v801 + v804;
        let v806: f64 = v183 * v670;
        let v807: f64 = v112 * v677;
        let v808: f64 = v136 * v681;
        let v809: f64 = v807 + v808;
        let v810: f64 = v806 + v809;
        let v811: f64 = v805 + v810;
        let v812: f64 = v68 * v811;
        let v813: f64 = v800 - v812;
        let v814: f64 = v790 + v813;
        let v815: f64 = v10 * v814;
        let v816: f64 = v785 - v815;
        let v817: f64 = v48 * v816;
        let v818: f64 = v762 + v817;
        let v819: f64 = v634 + v818;
        let v820: f64 = v262 * v629;
        let v821: f64 = v28 * v622;
        let v822: f64 = v820 + v821;
        let v823: f64 = v170 * v629;
        let v824: f64 = v173 * v639;
        let v825: f64 = v60 * v635;
        let v826: f64 = v824 - v825;
        let v827: f64 = v823 + v826;
        let v828: f64 = v68 * v799;
        let v829: f64 = v65 * v811;
        let v830: f64 = v828 + v829;
        let v831: f64 = v827 + v830;
        let v832: f64 = v822 + v831;
        let v833: f64 = v29 * v832;
        let v834: f64 = v819 + v833;
        let v835: f64 = v15 * v834;
        let v836: f64 = v277 * v18;
        let v837: f64 = v835 - v836;
        let v838: f64 = v322 * v15;
        let v839: f64 = v22 * v622;
        let v840: f64 = v280 * v626;
        let v841: f64 = v839 - v840;
        let v842: f64 = v283 * v631;
        let v843: f64 = v28 * v643;
        let v844: f64 = v842 + v843;
        let v845: f64 = v841 - v844;
        let v846: f64 = v44 * v635;
        let v847: f64 = v289 * v626;
        let v848: f64 = v846 - v847;
        let v849: f64 = v203 * v639;
        let v850: f64 = v848 + v849;
        let v851: f64 = v60 * v668;
        let v852: f64 = v173 * v647;
        let v853: f64 = v851 - v852;
        let v854: f64 = v850 + v853;
        let v855: f64 = v68 * v711;
        let v856: f64 = v65 * v731;
        let v857: f64 = v855 + v856;
        let v858: f64 = v854 + v857;
        let v859: f64 = v845 + v858;
        let v860: f64 = v48 * v814;
        let v861: f64 = v40 * v759;
        let v862: f64 = v860 - v861;
        let v863: f64 = v262 * v631;
        let v864: f64 = v283 * v626;
        let v865: f64 = v32 * v622;
        let v866: f64 = v864 + v865;
        let v867: f64 = v863 + v866;
        let v868: f64 = v862 - v867;
        let v869: f64 = v33 * v868;
        let v870: f64 = v40 * v814;
        let v871: f64 = v48 * v759;
        let v872: f64 = v870 + v871;
        let v873: f64 = v262 * v643;
        let v874: f64 = v28 * v626;
        let v875: f64 = v873 + v874;
        let v876: f64 = v872 + v875;
        let v877: f64 = v29 * v876;
        let v878: f64 = v869 - v877;
        let v879: f64 = v859 + v878;
        let v880: f64 = v18 * v879;
        let v881: f64 = v838 + v880;
        let v882: f64 = v837 - v881;
        let v883: f64 = v3 * v882;
        let v884: f64 = v277 * v15;
        let v885: f64 = v18 * v834;
        let v886: f64 = v884 + v885;
        let v887: f64 = v15 * v879;
        let v888: f64 = v322 * v18;
        let v889: f64 = v887 - v888;
        let v890: f64 = v886 + v889;
        let v891: f64 = v10 * v868;
        let v892: f64 = v890 + v891;
        let v893: f64 = v6 * v892;
        let v894: f64 = v883 + v893;
        let v895: f64 = v0 * v894;
        let v896: f64 = qd[2];
        let v897: f64 = v895 * v896;
        let v898: f64 = v619 + v897;
        let v899: f64 = v20 * v40;
        let v900: f64 = v47 * v899;
        let v901: f64 = v20 * v48;
        let v902: f64 = v41 * v901;
        let v903: f64 = v900 - v902;
        let v904: f64 = v10 * v901;
        let v905: f64 = v54 * v40;
        let v906: f64 = v35 * v48;
        let v907: f64 = v905 - v906;
        let v908: f64 = v904 + v907;
        let v909: f64 = v52 * v908;
        let v910: f64 = v903 - v909;
        let v911: f64 = v68 * v901;
        let v912: f64 = v75 * v911;
        let v913: f64 = v65 * v901;
        let v914: f64 = v66 * v913;
        let v915: f64 = v72 * v899;
        let v916: f64 = v914 + v915;
        let v917: f64 = v912 - v916;
        let v918: f64 = v35 * v40;
        let v919: f64 = v54 * v48;
        let v920: f64 = v918 + v919;
        let v921: f64 = v10 * v899;
        let v922: f64 = v920 - v921;
        let v923: f64 = v68 * v922;
        let v924: f64 = v81 * v923;
        let v925: f64 = v91 * v908;
        let v926: f64 = v924 + v925;
        let v927: f64 = v917 - v926;
        let v928: f64 = v109 * v911;
        let v929: f64 = v96 * v913;
        let v930: f64 = v99 * v899;
        let v931: f64 = v929 + v930;
        let v932: f64 = v97 * v931;
        let v933: f64 = v96 * v899;
        let v934: f64 = v99 * v913;
        let v935: f64 = v933 - v934;
        let v936: f64 = v103 * v935;
        let v937: f64 = v932 + v936;
        let v938: f64 = v928 - v937;
        let v939: f64 = v65 * v922;
        let v940: f64 = v99 * v939;
        let v941: f64 = v96 * v908;
        let v942: f64 = v940 - v941;
        let v943: f64 = v114 * v942;
        let v944: f64 = v112 * v923;
        let v945: f64 = v943 - v944;
        let v946: f64 = v938 + v945;
        let v947: f64 = v96 * v946;
        let v948: f64 = v129 * v911;
        let v949: f64 = v103 * v931;
        let v950: f64 = v126 * v935;
        let v951: f64 = v949 + v950;
        let v952: f64 = v948 - v951;
        let v953: f64 = v96 * v939;
        let v954: f64 = v99 * v908;
        let v955: f64 = v953 + v954;
        let v956: f64 = v114 * v955;
        let v957: f64 = v136 * v923;
        let v958: f64 = v956 + v957;
        let v959: f64 = v952 + v958;
        let v960: f64 = v99 * v959;
        let v961: f64 = v947 - v960;
        let v962: f64 = v927 + v961;
        let v963: f64 = v65 * v962;
        let v964: f64 = v148 * v911;
        let v965: f64 = v75 * v913;
        let v966: f64 = v145 * v899;
        let v967: f64 = v965 + v966;
        let v968: f64 = v964 - v967;
        let v969: f64 = v81 * v939;
        let v970: f64 = v151 * v908;
        let v971: f64 = v969 - v970;
        let v972: f64 = v968 - v971;
        let v973: f64 = v159 * v911;
        let v974: f64 = v109 * v931;
        (
            v784,
            v816,
            v832,
            v858,
            v876,
            v895,
            v896,
            v898,
            v899,
            v901,
            v908,
            v910,
            v911,
            v913,
            v922,
            v923,
            v931,
            v935,
            v939,
            v942,
            v946,
            v955,
            v959,
            v962,
            v963,
            v972,
            v973,
            v974,
        )
    };
    let (
        v981,
        v1010,
        v1032,
        v1062,
        v1072,
        v1086,
        v1101,
        v1115,
        v1116,
        v1118,
        v1121,
        v1125,
        v1130,
        v1133,
        v1135,
        v1142,
        v1143,
        v1147,
        v1154,
        v1158,
        v1161,
        v1164,
        v1165,
        v1168,
        v1169,
    ) = {
        let v975: f64 = v129 * v935;
        let v976: f64 = v974 + v975;
        let v977: f64 = v973 - v976;
        let v978: f64 = v136 * v942;
        let v979: f64 = v112 * v955;
        let v980: f64 = v978 + v979;
        let v981: f64 = v977 - v980;
        let v982: f64 = v972 + v981;
        let v983: f64 = v68 * v982;
        let v984: f64 = v963 - v983;
        let v985: f64 = v910 + v984;
        let v986: f64 = v170 * v908;
        let v987: f64 = v52 * v901;
        let v988: f64 = v986 + v987;
        let v989: f64 = v151 * v911;
        let v990: f64 = v91 * v913;
        let v991: f64 = v989 + v990;
        let v992: f64 = v180 * v908;
        let v993: f64 = v991 + v992;
        let v994: f64 = v183 * v955;
        let v995: f64 = v114 * v935;
        let v996: f64 = v112 * v911;
        let v997: f64 = v995 + v996;
        let v998: f64 = v994 - v997;
        let v999: f64 = v99 * v998;
        let v1000: f64 = v136 * v911;
        let v1001: f64 = v114 * v931;
        let v1002: f64 = v1000 + v1001;
        let v1003: f64 = v183 * v942;
        let v1004: f64 = v1002 - v1003;
        let v1005: f64 = v96 * v1004;
        let v1006: f64 = v999 + v1005;
        let v1007: f64 = v993 + v1006;
        let v1008: f64 = v988 + v1007;
        let v1009: f64 = v10 * v1008;
        let v1010: f64 = v985 - v1009;
        let v1011: f64 = v40 * v1010;
        let v1012: f64 = v200 * v48;
        let v1013: f64 = v1011 - v1012;
        let v1014: f64 = v258 * v40;
        let v1015: f64 = v206 * v899;
        let v1016: f64 = v47 * v901;
        let v1017: f64 = v1015 - v1016;
        let v1018: f64 = v52 * v922;
        let v1019: f64 = v1017 - v1018;
        let v1020: f64 = v145 * v911;
        let v1021: f64 = v72 * v913;
        let v1022: f64 = v214 * v899;
        let v1023: f64 = v1021 + v1022;
        let v1024: f64 = v1020 - v1023;
        let v1025: f64 = v91 * v939;
        let v1026: f64 = v151 * v923;
        let v1027: f64 = v1025 + v1026;
        let v1028: f64 = v1024 + v1027;
        let v1029: f64 = v99 * v946;
        let v1030: f64 = v96 * v959;
        let v1031: f64 = v1029 + v1030;
        let v1032: f64 = v1028 + v1031;
        let v1033: f64 = v1019 - v1032;
        let v1034: f64 = v170 * v922;
        let v1035: f64 = v52 * v899;
        let v1036: f64 = v1034 - v1035;
        let v1037: f64 = v180 * v939;
        let v1038: f64 = v91 * v899;
        let v1039: f64 = v81 * v911;
        let v1040: f64 = v1038 + v1039;
        let v1041: f64 = v1037 - v1040;
        let v1042: f64 = v96 * v998;
        let v1043: f64 = v99 * v1004;
        let v1044: f64 = v1042 - v1043;
        let v1045: f64 = v1041 + v1044;
        let v1046: f64 = v65 * v1045;
        let v1047: f64 = v151 * v899;
        let v1048: f64 = v81 * v913;
        let v1049: f64 = v1047 - v1048;
        let v1050: f64 = v180 * v923;
        let v1051: f64 = v1049 - v1050;
        let v1052: f64 = v136 * v935;
        let v1053: f64 = v112 * v931;
        let v1054: f64 = v1052 - v1053;
        let v1055: f64 = v183 * v923;
        let v1056: f64 = v1054 - v1055;
        let v1057: f64 = v1051 + v1056;
        let v1058: f64 = v68 * v1057;
        let v1059: f64 = v1046 - v1058;
        let v1060: f64 = v1036 + v1059;
        let v1061: f64 = v10 * v1060;
        let v1062: f64 = v1033 - v1061;
        let v1063: f64 = v48 * v1062;
        let v1064: f64 = v1014 + v1063;
        let v1065: f64 = v1013 + v1064;
        let v1066: f64 = v173 * v899;
        let v1067: f64 = v60 * v901;
        let v1068: f64 = v1066 + v1067;
        let v1069: f64 = v68 * v1045;
        let v1070: f64 = v65 * v1057;
        let v1071: f64 = v1069 + v1070;
        let v1072: f64 = v1068 + v1071;
        let v1073: f64 = v29 * v1072;
        let v1074: f64 = v1065 + v1073;
        let v1075: f64 = v15 * v1074;
        let v1076: f64 = v203 * v899;
        let v1077: f64 = v44 * v901;
        let v1078: f64 = v1076 - v1077;
        let v1079: f64 = v60 * v922;
        let v1080: f64 = v173 * v908;
        let v1081: f64 = v1079 + v1080;
        let v1082: f64 = v1078 + v1081;
        let v1083: f64 = v68 * v962;
        let v1084: f64 = v65 * v982;
        let v1085: f64 = v1083 + v1084;
        let v1086: f64 = v1082 + v1085;
        let v1087: f64 = v256 * v40;
        let v1088: f64 = v48 * v1060;
        let v1089: f64 = v1087 + v1088;
        let v1090: f64 = v198 * v48;
        let v1091: f64 = v40 * v1008;
        let v1092: f64 = v1090 + v1091;
        let v1093: f64 = v1089 + v1092;
        let v1094: f64 = v33 * v1093;
        let v1095: f64 = v40 * v1060;
        let v1096: f64 = v256 * v48;
        let v1097: f64 = v1095 - v1096;
        let v1098: f64 = v198 * v40;
        let v1099: f64 = v48 * v1008;
        let v1100: f64 = v1098 - v1099;
        let v1101: f64 = v1097 + v1100;
        let v1102: f64 = v29 * v1101;
        let v1103: f64 = v1094 - v1102;
        let v1104: f64 = v1086 + v1103;
        let v1105: f64 = v18 * v1104;
        let v1106: f64 = v1075 - v1105;
        let v1107: f64 = v3 * v1106;
        let v1108: f64 = v18 * v1074;
        let v1109: f64 = v15 * v1104;
        let v1110: f64 = v1108 + v1109;
        let v1111: f64 = v10 * v1093;
        let v1112: f64 = v1110 + v1111;
        let v1113: f64 = v6 * v1112;
        let v1114: f64 = v1107 + v1113;
        let v1115: f64 = v0 * v1114;
        let v1116: f64 = qd[3];
        let v1117: f64 = v1115 * v1116;
        let v1118: f64 = v898 + v1117;
        let v1119: f64 = v25 * v65;
        let v1120: f64 = v42 * v68;
        let v1121: f64 = v1119 - v1120;
        let v1122: f64 = v66 * v1121;
        let v1123: f64 = v25 * v68;
        let v1124: f64 = v42 * v65;
        let v1125: f64 = v1123 + v1124;
        let v1126: f64 = v75 * v1125;
        let v1127: f64 = v1122 - v1126;
        let v1128: f64 = v30 * v68;
        let v1129: f64 = v87 * v65;
        let v1130: f64 = v1128 + v1129;
        let v1131: f64 = v81 * v1130;
        let v1132: f64 = v1127 - v1131;
        let v1133: f64 = v96 * v1121;
        let v1134: f64 = v97 * v1133;
        let v1135: f64 = v99 * v1121;
        let v1136: f64 = v103 * v1135;
        let v1137: f64 = v1134 - v1136;
        let v1138: f64 = v109 * v1125;
        let v1139: f64 = v1137 - v1138;
        let v1140: f64 = v30 * v65;
        let v1141: f64 = v87 * v68;
        let v1142: f64 = v1140 - v1141;
        let v1143: f64 = v99 * v1142;
        let v1144: f64 = v114 * v1143;
        let v1145: f64 = v112 * v1130;
        let v1146: f64 = v1144 - v1145;
        let v1147: f64 = v1139 + v1146;
        let v1148: f64 = v96 * v1147;
        let v1149: f64 = v103 * v1133;
        let v1150: f64 = v126 * v1135;
        let v1151: f64 = v1149 - v1150;
        let v1152: f64 = v129 * v1125;
        let v1153: f64 = v1151 - v1152;
        let v1154: f64 = v96 * v1142;
        let v1155: f64 = v114 * v1154;
        let v1156: f64 = v136 * v1130;
        let v1157: f64 = v1155 + v1156;
        let v1158: f64 = v1153 + v1157;
        let v1159: f64 = v99 * v1158;
        let v1160: f64 = v1148 - v1159;
        let v1161: f64 = v1132 + v1160;
        let v1162: f64 = v65 * v1161;
        let v1163: f64 = v142 * v68;
        let v1164: f64 = v1162 - v1163;
        let v1165: f64 = v166 * v65;
        let v1166: f64 = v75 * v1121;
        let v1167: f64 = v148 * v1125;
        let v1168: f64 = v1166 - v1167;
        let v1169: f64 = v81 * v1142;
        (
            v981,
            v1010,
            v1032,
            v1062,
            v1072,
            v1086,
            v1101,
            v1115,
            v1116,
            v1118,
            v1121,
            v1125,
            v1130,
            v1133,
            v1135,
            v1142,
            v1143,
            v1147,
            v1154,
            v1158,
            v1161,
            v1164,
            v1165,
            v1168,
            v1169,
        )
    };
    let (
        v1179,
        v1202,
        v1214,
        v1239,
        v1248,
        v1258,
        v1265,
        v1279,
        v1280,
        v1282,
        v1311,
        v1319,
        v1334,
        v1336,
        v1350,
        v1358,
        v1359,
        v1361,
        v1364,
    ) = {
        let v1170: f64 = v1168 - v1169;
        let v1171: f64 = v109 * v1133;
        let v1172: f64 = v129 * v1135;
        let v1173: f64 = v1171 - v1172;
        let v1174: f64 = v159 * v1125;
        let v1175: f64 = v1173 - v1174;
        let v1176: f64 = v136 * v1143;
        let v1177: f64 = v112 * v1154;
        let v1178: f64 = v1176 + v1177;
        let v1179: f64 = v1175 - v1178;
        let v1180: f64 = v1170 + v1179;
        let v1181: f64 = v68 * v1180;
        let v1182: f64 = v1165 + v1181;
        let v1183: f64 = v1164 - v1182;
        let v1184: f64 = v183 * v1154;
        let v1185: f64 = v114 * v1135;
        let v1186: f64 = v112 * v1125;
        let v1187: f64 = v1185 - v1186;
        let v1188: f64 = v1184 - v1187;
        let v1189: f64 = v99 * v1188;
        let v1190: f64 = v136 * v1125;
        let v1191: f64 = v114 * v1133;
        let v1192: f64 = v1190 + v1191;
        let v1193: f64 = v183 * v1143;
        let v1194: f64 = v1192 + v1193;
        let v1195: f64 = v96 * v1194;
        let v1196: f64 = v1189 - v1195;
        let v1197: f64 = v151 * v1125;
        let v1198: f64 = v91 * v1121;
        let v1199: f64 = v1197 + v1198;
        let v1200: f64 = v1196 - v1199;
        let v1201: f64 = v10 * v1200;
        let v1202: f64 = v1183 - v1201;
        let v1203: f64 = v40 * v1202;
        let v1204: f64 = v72 * v1121;
        let v1205: f64 = v145 * v1125;
        let v1206: f64 = v1204 - v1205;
        let v1207: f64 = v91 * v1142;
        let v1208: f64 = v151 * v1130;
        let v1209: f64 = v1207 + v1208;
        let v1210: f64 = v1206 + v1209;
        let v1211: f64 = v99 * v1147;
        let v1212: f64 = v96 * v1158;
        let v1213: f64 = v1211 + v1212;
        let v1214: f64 = v1210 + v1213;
        let v1215: f64 = v180 * v1142;
        let v1216: f64 = v81 * v1125;
        let v1217: f64 = v1215 + v1216;
        let v1218: f64 = v96 * v1188;
        let v1219: f64 = v99 * v1194;
        let v1220: f64 = v1218 + v1219;
        let v1221: f64 = v1217 + v1220;
        let v1222: f64 = v65 * v1221;
        let v1223: f64 = v241 * v68;
        let v1224: f64 = v1222 - v1223;
        let v1225: f64 = v253 * v65;
        let v1226: f64 = v81 * v1121;
        let v1227: f64 = v180 * v1130;
        let v1228: f64 = v1226 - v1227;
        let v1229: f64 = v112 * v1133;
        let v1230: f64 = v136 * v1135;
        let v1231: f64 = v1229 + v1230;
        let v1232: f64 = v183 * v1130;
        let v1233: f64 = v1231 - v1232;
        let v1234: f64 = v1228 + v1233;
        let v1235: f64 = v68 * v1234;
        let v1236: f64 = v1225 + v1235;
        let v1237: f64 = v1224 - v1236;
        let v1238: f64 = v10 * v1237;
        let v1239: f64 = v1214 + v1238;
        let v1240: f64 = v48 * v1239;
        let v1241: f64 = v1203 - v1240;
        let v1242: f64 = v241 * v65;
        let v1243: f64 = v68 * v1221;
        let v1244: f64 = v1242 + v1243;
        let v1245: f64 = v65 * v1234;
        let v1246: f64 = v253 * v68;
        let v1247: f64 = v1245 - v1246;
        let v1248: f64 = v1244 + v1247;
        let v1249: f64 = v29 * v1248;
        let v1250: f64 = v1241 + v1249;
        let v1251: f64 = v15 * v1250;
        let v1252: f64 = v142 * v65;
        let v1253: f64 = v68 * v1161;
        let v1254: f64 = v1252 + v1253;
        let v1255: f64 = v65 * v1180;
        let v1256: f64 = v166 * v68;
        let v1257: f64 = v1255 - v1256;
        let v1258: f64 = v1254 + v1257;
        let v1259: f64 = v48 * v1237;
        let v1260: f64 = v40 * v1200;
        let v1261: f64 = v1259 + v1260;
        let v1262: f64 = v33 * v1261;
        let v1263: f64 = v40 * v1237;
        let v1264: f64 = v48 * v1200;
        let v1265: f64 = v1263 - v1264;
        let v1266: f64 = v29 * v1265;
        let v1267: f64 = v1262 - v1266;
        let v1268: f64 = v1258 + v1267;
        let v1269: f64 = v18 * v1268;
        let v1270: f64 = v1251 - v1269;
        let v1271: f64 = v3 * v1270;
        let v1272: f64 = v18 * v1250;
        let v1273: f64 = v15 * v1268;
        let v1274: f64 = v1272 + v1273;
        let v1275: f64 = v10 * v1261;
        let v1276: f64 = v1274 + v1275;
        let v1277: f64 = v6 * v1276;
        let v1278: f64 = v1271 + v1277;
        let v1279: f64 = v0 * v1278;
        let v1280: f64 = qd[4];
        let v1281: f64 = v1279 * v1280;
        let v1282: f64 = v1118 + v1281;
        let v1283: f64 = v117 * v96;
        let v1284: f64 = v58 * v99;
        let v1285: f64 = v1283 - v1284;
        let v1286: f64 = v114 * v1285;
        let v1287: f64 = v70 * v99;
        let v1288: f64 = v49 * v96;
        let v1289: f64 = v1287 + v1288;
        let v1290: f64 = v97 * v1289;
        let v1291: f64 = v70 * v96;
        let v1292: f64 = v49 * v99;
        let v1293: f64 = v1291 - v1292;
        let v1294: f64 = v103 * v1293;
        let v1295: f64 = v1290 + v1294;
        let v1296: f64 = v1286 - v1295;
        let v1297: f64 = v96 * v1296;
        let v1298: f64 = v123 * v99;
        let v1299: f64 = v1297 - v1298;
        let v1300: f64 = v139 * v96;
        let v1301: f64 = v103 * v1289;
        let v1302: f64 = v126 * v1293;
        let v1303: f64 = v1301 + v1302;
        let v1304: f64 = v117 * v99;
        let v1305: f64 = v58 * v96;
        let v1306: f64 = v1304 + v1305;
        let v1307: f64 = v114 * v1306;
        let v1308: f64 = v1303 + v1307;
        let v1309: f64 = v99 * v1308;
        let v1310: f64 = v1300 - v1309;
        let v1311: f64 = v1299 - v1310;
        let v1312: f64 = v65 * v1311;
        let v1313: f64 = v109 * v1289;
        let v1314: f64 = v129 * v1293;
        let v1315: f64 = v1313 + v1314;
        let v1316: f64 = v136 * v1285;
        let v1317: f64 = v112 * v1306;
        let v1318: f64 = v1316 - v1317;
        let v1319: f64 = v1315 + v1318;
        let v1320: f64 = v68 * v1319;
        let v1321: f64 = v1312 + v1320;
        let v1322: f64 = v188 * v96;
        let v1323: f64 = v183 * v1306;
        let v1324: f64 = v114 * v1293;
        let v1325: f64 = v1323 + v1324;
        let v1326: f64 = v99 * v1325;
        let v1327: f64 = v1322 - v1326;
        let v1328: f64 = v114 * v1289;
        let v1329: f64 = v183 * v1285;
        let v1330: f64 = v1328 - v1329;
        let v1331: f64 = v96 * v1330;
        let v1332: f64 = v194 * v99;
        let v1333: f64 = v1331 - v1332;
        let v1334: f64 = v1327 + v1333;
        let v1335: f64 = v10 * v1334;
        let v1336: f64 = v1321 - v1335;
        let v1337: f64 = v40 * v1336;
        let v1338: f64 = v188 * v99;
        let v1339: f64 = v96 * v1325;
        let v1340: f64 = v1338 + v1339;
        let v1341: f64 = v194 * v96;
        let v1342: f64 = v99 * v1330;
        let v1343: f64 = v1341 + v1342;
        let v1344: f64 = v1340 + v1343;
        let v1345: f64 = v65 * v1344;
        let v1346: f64 = v136 * v1293;
        let v1347: f64 = v112 * v1289;
        let v1348: f64 = v1346 - v1347;
        let v1349: f64 = v68 * v1348;
        let v1350: f64 = v1345 + v1349;
        let v1351: f64 = v10 * v1350;
        let v1352: f64 = v123 * v96;
        let v1353: f64 = v99 * v1296;
        let v1354: f64 = v1352 + v1353;
        let v1355: f64 = v139 * v99;
        let v1356: f64 = v96 * v1308;
        let v1357: f64 = v1355 + v1356;
        let v1358: f64 = v1354 - v1357;
        let v1359: f64 = v1351 - v1358;
        let v1360: f64 = v48 * v1359;
        let v1361: f64 = v1337 + v1360;
        let v1362: f64 = v65 * v1348;
        let v1363: f64 = v68 * v1344;
        let v1364: f64 = v1362 - v1363;
        (
            v1179,
            v1202,
            v1214,
            v1239,
            v1248,
            v1258,
            v1265,
            v1279,
            v1280,
            v1282,
            v1311,
            v1319,
            v1334,
            v1336,
            v1350,
            v1358,
            v1359,
            v1361,
            v1364,
        )
    };
    let (
        v1370,
        v1377,
        v1391,
        v1392,
        v1394,
        v1395,
        v1396,
        v1397,
        v1398,
        v1400,
        v1401,
        v1402,
        v1404,
        v1405,
        v1406,
        v1408,
        v1409,
        v1411,
        v1412,
        v1419,
        v1423,
        v1426,
        v1427,
        v1437,
        v1441,
        v1444,
        v1448,
        v1454,
        v1460,
        v1467,
        v1470,
        v1476,
        v1485,
        v1490,
        v1495,
        v1499,
        v1505,
        v1506,
        v1510,
        v1512,
        v1516,
        v1518,
        v1519,
        v1521,
        v1522,
        v1531,
        v1540,
        v1542,
        v1543,
        v1547,
        v1552,
        v1553,
        v1557,
        v1558,
        v1559,
    ) = {
        let v1365: f64 = v29 * v1364;
        let v1366: f64 = v1361 + v1365;
        let v1367: f64 = v15 * v1366;
        let v1368: f64 = v68 * v1311;
        let v1369: f64 = v65 * v1319;
        let v1370: f64 = v1368 - v1369;
        let v1371: f64 = v40 * v1334;
        let v1372: f64 = v48 * v1350;
        let v1373: f64 = v1371 - v1372;
        let v1374: f64 = v33 * v1373;
        let v1375: f64 = v40 * v1350;
        let v1376: f64 = v48 * v1334;
        let v1377: f64 = v1375 + v1376;
        let v1378: f64 = v29 * v1377;
        let v1379: f64 = v1374 + v1378;
        let v1380: f64 = v1370 + v1379;
        let v1381: f64 = v18 * v1380;
        let v1382: f64 = v1367 - v1381;
        let v1383: f64 = v3 * v1382;
        let v1384: f64 = v18 * v1366;
        let v1385: f64 = v15 * v1380;
        let v1386: f64 = v1384 + v1385;
        let v1387: f64 = v10 * v1373;
        let v1388: f64 = v1386 + v1387;
        let v1389: f64 = v6 * v1388;
        let v1390: f64 = v1383 + v1389;
        let v1391: f64 = v0 * v1390;
        let v1392: f64 = qd[5];
        let v1393: f64 = v1391 * v1392;
        let v1394: f64 = v1282 + v1393;
        let v1395: f64 = qd[0];
        let v1396: f64 = v617 * v1395;
        let v1397: f64 = params[16];
        let v1398: f64 = params[13];
        let v1399: f64 = v10 * v1398;
        let v1400: f64 = v1397 - v1399;
        let v1401: f64 = v10 * v15;
        let v1402: f64 = v1401 + v33;
        let v1403: f64 = v28 * v1402;
        let v1404: f64 = params[25];
        let v1405: f64 = v1403 - v1404;
        let v1406: f64 = v47 * v40;
        let v1407: f64 = v41 * v48;
        let v1408: f64 = v1406 - v1407;
        let v1409: f64 = v10 * v18;
        let v1410: f64 = v48 * v1409;
        let v1411: f64 = v10 * v48;
        let v1412: f64 = v1410 - v1411;
        let v1413: f64 = v52 * v1412;
        let v1414: f64 = v60 * v1402;
        let v1415: f64 = v1413 - v1414;
        let v1416: f64 = v1408 + v1415;
        let v1417: f64 = v68 * v48;
        let v1418: f64 = v75 * v1417;
        let v1419: f64 = v65 * v48;
        let v1420: f64 = v66 * v1419;
        let v1421: f64 = v72 * v40;
        let v1422: f64 = v1420 + v1421;
        let v1423: f64 = v1418 - v1422;
        let v1424: f64 = v65 * v1402;
        let v1425: f64 = v40 * v1409;
        let v1426: f64 = v10 * v40;
        let v1427: f64 = v1425 - v1426;
        let v1428: f64 = v68 * v1427;
        let v1429: f64 = v1424 - v1428;
        let v1430: f64 = v81 * v1429;
        let v1431: f64 = v91 * v1412;
        let v1432: f64 = v1430 + v1431;
        let v1433: f64 = v1423 + v1432;
        let v1434: f64 = v109 * v1417;
        let v1435: f64 = v96 * v1419;
        let v1436: f64 = v99 * v40;
        let v1437: f64 = v1435 + v1436;
        let v1438: f64 = v97 * v1437;
        let v1439: f64 = v96 * v40;
        let v1440: f64 = v99 * v1419;
        let v1441: f64 = v1439 - v1440;
        let v1442: f64 = v103 * v1441;
        let v1443: f64 = v1438 + v1442;
        let v1444: f64 = v1434 - v1443;
        let v1445: f64 = v112 * v1429;
        let v1446: f64 = v65 * v1427;
        let v1447: f64 = v68 * v1402;
        let v1448: f64 = v1446 + v1447;
        let v1449: f64 = v99 * v1448;
        let v1450: f64 = v96 * v1412;
        let v1451: f64 = v1449 + v1450;
        let v1452: f64 = v114 * v1451;
        let v1453: f64 = v1445 + v1452;
        let v1454: f64 = v1444 + v1453;
        let v1455: f64 = v96 * v1454;
        let v1456: f64 = v129 * v1417;
        let v1457: f64 = v103 * v1437;
        let v1458: f64 = v126 * v1441;
        let v1459: f64 = v1457 + v1458;
        let v1460: f64 = v1456 - v1459;
        let v1461: f64 = v96 * v1448;
        let v1462: f64 = v99 * v1412;
        let v1463: f64 = v1461 - v1462;
        let v1464: f64 = v114 * v1463;
        let v1465: f64 = v136 * v1429;
        let v1466: f64 = v1464 - v1465;
        let v1467: f64 = v1460 + v1466;
        let v1468: f64 = v99 * v1467;
        let v1469: f64 = v1455 - v1468;
        let v1470: f64 = v1433 + v1469;
        let v1471: f64 = v65 * v1470;
        let v1472: f64 = v148 * v1417;
        let v1473: f64 = v75 * v1419;
        let v1474: f64 = v145 * v40;
        let v1475: f64 = v1473 + v1474;
        let v1476: f64 = v1472 - v1475;
        let v1477: f64 = v151 * v1412;
        let v1478: f64 = v81 * v1448;
        let v1479: f64 = v1477 + v1478;
        let v1480: f64 = v1476 - v1479;
        let v1481: f64 = v159 * v1417;
        let v1482: f64 = v109 * v1437;
        let v1483: f64 = v129 * v1441;
        let v1484: f64 = v1482 + v1483;
        let v1485: f64 = v1481 - v1484;
        let v1486: f64 = v136 * v1451;
        let v1487: f64 = v112 * v1463;
        let v1488: f64 = v1486 + v1487;
        let v1489: f64 = v1485 - v1488;
        let v1490: f64 = v1480 + v1489;
        let v1491: f64 = v68 * v1490;
        let v1492: f64 = v1471 - v1491;
        let v1493: f64 = v1416 + v1492;
        let v1494: f64 = v170 * v1412;
        let v1495: f64 = v52 * v48;
        let v1496: f64 = v1494 - v1495;
        let v1497: f64 = v151 * v1417;
        let v1498: f64 = v91 * v1419;
        let v1499: f64 = v1497 + v1498;
        let v1500: f64 = v180 * v1412;
        let v1501: f64 = v1499 - v1500;
        let v1502: f64 = v183 * v1463;
        let v1503: f64 = v114 * v1441;
        let v1504: f64 = v112 * v1417;
        let v1505: f64 = v1503 + v1504;
        let v1506: f64 = v1502 - v1505;
        let v1507: f64 = v99 * v1506;
        let v1508: f64 = v136 * v1417;
        let v1509: f64 = v114 * v1437;
        let v1510: f64 = v1508 + v1509;
        let v1511: f64 = v183 * v1451;
        let v1512: f64 = v1510 - v1511;
        let v1513: f64 = v96 * v1512;
        let v1514: f64 = v1507 + v1513;
        let v1515: f64 = v1501 + v1514;
        let v1516: f64 = v1496 - v1515;
        let v1517: f64 = v10 * v1516;
        let v1518: f64 = v1493 + v1517;
        let v1519: f64 = v40 * v1518;
        let v1520: f64 = v206 * v40;
        let v1521: f64 = v47 * v48;
        let v1522: f64 = v1520 - v1521;
        let v1523: f64 = v173 * v1402;
        let v1524: f64 = v52 * v1427;
        let v1525: f64 = v1523 - v1524;
        let v1526: f64 = v1522 + v1525;
        let v1527: f64 = v145 * v1417;
        let v1528: f64 = v72 * v1419;
        let v1529: f64 = v214 * v40;
        let v1530: f64 = v1528 + v1529;
        let v1531: f64 = v1527 - v1530;
        let v1532: f64 = v91 * v1448;
        let v1533: f64 = v151 * v1429;
        let v1534: f64 = v1532 - v1533;
        let v1535: f64 = v1531 + v1534;
        let v1536: f64 = v99 * v1454;
        let v1537: f64 = v96 * v1467;
        let v1538: f64 = v1536 + v1537;
        let v1539: f64 = v1535 + v1538;
        let v1540: f64 = v1526 - v1539;
        let v1541: f64 = v170 * v1427;
        let v1542: f64 = v52 * v40;
        let v1543: f64 = v1541 - v1542;
        let v1544: f64 = v180 * v1448;
        let v1545: f64 = v91 * v40;
        let v1546: f64 = v81 * v1417;
        let v1547: f64 = v1545 + v1546;
        let v1548: f64 = v1544 - v1547;
        let v1549: f64 = v96 * v1506;
        let v1550: f64 = v99 * v1512;
        let v1551: f64 = v1549 - v1550;
        let v1552: f64 = v1548 + v1551;
        let v1553: f64 = v65 * v1552;
        let v1554: f64 = v180 * v1429;
        let v1555: f64 = v151 * v40;
        let v1556: f64 = v81 * v1419;
        let v1557: f64 = v1555 - v1556;
        let v1558: f64 = v1554 + v1557;
        let v1559: f64 = v183 * v1429;
        (
            v1370,
            v1377,
            v1391,
            v1392,
            v1394,
            v1395,
            v1396,
            v1397,
            v1398,
            v1400,
            v1401,
            v1402,
            v1404,
            v1405,
            v1406,
            v1408,
            v1409,
            v1411,
            v1412,
            v1419,
            v1423,
            v1426,
            v1427,
            v1437,
            v1441,
            v1444,
            v1448,
            v1454,
            v1460,
            v1467,
            v1470,
            v1476,
            v1485,
            v1490,
            v1495,
            v1499,
            v1505,
            v1506,
            v1510,
            v1512,
            v1516,
            v1518,
            v1519,
            v1521,
            v1522,
            v1531,
            v1540,
            v1542,
            v1543,
            v1547,
            v1552,
            v1553,
            v1557,
            v1558,
            v1559,
        )
    };
    let (
        v1562,
        v1564,
        v1567,
        v1569,
        v1578,
        v1584,
        v1590,
        v1599,
        v1612,
        v1615,
        v1620,
        v1628,
        v1632,
        v1669,
        v1684,
        v1695,
        v1711,
        v1720,
        v1733,
        v1738,
        v1744,
        v1747,
        v1751,
        v1754,
    ) = {
        let v1560: f64 = v136 * v1441;
        let v1561: f64 = v112 * v1437;
        let v1562: f64 = v1560 - v1561;
        let v1563: f64 = v1559 + v1562;
        let v1564: f64 = v1558 + v1563;
        let v1565: f64 = v68 * v1564;
        let v1566: f64 = v1553 - v1565;
        let v1567: f64 = v1543 + v1566;
        let v1568: f64 = v10 * v1567;
        let v1569: f64 = v1540 - v1568;
        let v1570: f64 = v48 * v1569;
        let v1571: f64 = v1519 + v1570;
        let v1572: f64 = v1405 + v1571;
        let v1573: f64 = v262 * v1402;
        let v1574: f64 = v1573 + v283;
        let v1575: f64 = v170 * v1402;
        let v1576: f64 = v173 * v40;
        let v1577: f64 = v60 * v48;
        let v1578: f64 = v1576 + v1577;
        let v1579: f64 = v1575 + v1578;
        let v1580: f64 = v68 * v1552;
        let v1581: f64 = v65 * v1564;
        let v1582: f64 = v1580 + v1581;
        let v1583: f64 = v1579 + v1582;
        let v1584: f64 = v1574 + v1583;
        let v1585: f64 = v29 * v1584;
        let v1586: f64 = v1572 + v1585;
        let v1587: f64 = v15 * v1586;
        let v1588: f64 = v203 * v40;
        let v1589: f64 = v44 * v48;
        let v1590: f64 = v1588 - v1589;
        let v1591: f64 = v60 * v1427;
        let v1592: f64 = v173 * v1412;
        let v1593: f64 = v1591 - v1592;
        let v1594: f64 = v1590 + v1593;
        let v1595: f64 = v68 * v1470;
        let v1596: f64 = v65 * v1490;
        let v1597: f64 = v1595 + v1596;
        let v1598: f64 = v1594 + v1597;
        let v1599: f64 = params[28];
        let v1600: f64 = v28 * v1409;
        let v1601: f64 = v1599 + v1600;
        let v1602: f64 = v1598 - v1601;
        let v1603: f64 = v48 * v1567;
        let v1604: f64 = v40 * v1516;
        let v1605: f64 = v1603 - v1604;
        let v1606: f64 = v33 * v1605;
        let v1607: f64 = v262 * v1409;
        let v1608: f64 = v1607 - v32;
        let v1609: f64 = v40 * v1567;
        let v1610: f64 = v48 * v1516;
        let v1611: f64 = v1609 + v1610;
        let v1612: f64 = v1608 + v1611;
        let v1613: f64 = v29 * v1612;
        let v1614: f64 = v1606 - v1613;
        let v1615: f64 = v1602 + v1614;
        let v1616: f64 = v18 * v1615;
        let v1617: f64 = v1587 - v1616;
        let v1618: f64 = v1400 + v1617;
        let v1619: f64 = v1618 * v6;
        let v1620: f64 = params[18];
        let v1621: f64 = v18 * v1586;
        let v1622: f64 = v15 * v1615;
        let v1623: f64 = v1621 + v1622;
        let v1624: f64 = v1620 + v1623;
        let v1625: f64 = v10 * v1605;
        let v1626: f64 = v1624 + v1625;
        let v1627: f64 = v1626 * v3;
        let v1628: f64 = v1619 - v1627;
        let v1629: f64 = v1628 + v1628;
        let v1630: f64 = v0 * v1629;
        let v1631: f64 = v1630 * v618;
        let v1632: f64 = v1396 + v1631;
        let v1633: f64 = v48 * v1401;
        let v1634: f64 = v52 * v1633;
        let v1635: f64 = v60 * v1409;
        let v1636: f64 = v1634 + v1635;
        let v1637: f64 = v91 * v1633;
        let v1638: f64 = v65 * v1409;
        let v1639: f64 = v40 * v1401;
        let v1640: f64 = v68 * v1639;
        let v1641: f64 = v1638 + v1640;
        let v1642: f64 = v81 * v1641;
        let v1643: f64 = v1637 - v1642;
        let v1644: f64 = v65 * v1639;
        let v1645: f64 = v68 * v1409;
        let v1646: f64 = v1644 - v1645;
        let v1647: f64 = v99 * v1646;
        let v1648: f64 = v96 * v1633;
        let v1649: f64 = v1647 + v1648;
        let v1650: f64 = v114 * v1649;
        let v1651: f64 = v112 * v1641;
        let v1652: f64 = v1650 - v1651;
        let v1653: f64 = v96 * v1652;
        let v1654: f64 = v96 * v1646;
        let v1655: f64 = v99 * v1633;
        let v1656: f64 = v1654 - v1655;
        let v1657: f64 = v114 * v1656;
        let v1658: f64 = v136 * v1641;
        let v1659: f64 = v1657 + v1658;
        let v1660: f64 = v99 * v1659;
        let v1661: f64 = v1653 - v1660;
        let v1662: f64 = v1643 + v1661;
        let v1663: f64 = v65 * v1662;
        let v1664: f64 = v151 * v1633;
        let v1665: f64 = v81 * v1646;
        let v1666: f64 = v1664 + v1665;
        let v1667: f64 = v136 * v1649;
        let v1668: f64 = v112 * v1656;
        let v1669: f64 = v1667 + v1668;
        let v1670: f64 = v1666 + v1669;
        let v1671: f64 = v68 * v1670;
        let v1672: f64 = v1663 + v1671;
        let v1673: f64 = v1636 + v1672;
        let v1674: f64 = v170 * v1633;
        let v1675: f64 = v183 * v1656;
        let v1676: f64 = v99 * v1675;
        let v1677: f64 = v183 * v1649;
        let v1678: f64 = v96 * v1677;
        let v1679: f64 = v1676 - v1678;
        let v1680: f64 = v180 * v1633;
        let v1681: f64 = v1679 - v1680;
        let v1682: f64 = v1674 - v1681;
        let v1683: f64 = v10 * v1682;
        let v1684: f64 = v1673 + v1683;
        let v1685: f64 = v40 * v1684;
        let v1686: f64 = v173 * v1409;
        let v1687: f64 = v52 * v1639;
        let v1688: f64 = v1686 + v1687;
        let v1689: f64 = v91 * v1646;
        let v1690: f64 = v151 * v1641;
        let v1691: f64 = v1689 + v1690;
        let v1692: f64 = v99 * v1652;
        let v1693: f64 = v96 * v1659;
        let v1694: f64 = v1692 + v1693;
        let v1695: f64 = v1691 + v1694;
        let v1696: f64 = v1688 + v1695;
        let v1697: f64 = v170 * v1639;
        let v1698: f64 = v180 * v1646;
        let v1699: f64 = v96 * v1675;
        let v1700: f64 = v99 * v1677;
        let v1701: f64 = v1699 + v1700;
        let v1702: f64 = v1698 + v1701;
        let v1703: f64 = v65 * v1702;
        let v1704: f64 = v180 * v1641;
        let v1705: f64 = v183 * v1641;
        let v1706: f64 = v1704 + v1705;
        let v1707: f64 = v68 * v1706;
        let v1708: f64 = v1703 + v1707;
        let v1709: f64 = v1697 + v1708;
        let v1710: f64 = v10 * v1709;
        let v1711: f64 = v1696 + v1710;
        let v1712: f64 = v48 * v1711;
        let v1713: f64 = v1685 - v1712;
        let v1714: f64 = v1713 - v1600;
        let v1715: f64 = v68 * v1702;
        let v1716: f64 = v65 * v1706;
        let v1717: f64 = v1715 - v1716;
        let v1718: f64 = v170 * v1409;
        let v1719: f64 = v1717 - v1718;
        let v1720: f64 = v1719 - v1607;
        let v1721: f64 = v29 * v1720;
        let v1722: f64 = v1714 + v1721;
        let v1723: f64 = v15 * v1722;
        let v1724: f64 = v1586 * v18;
        let v1725: f64 = v1723 - v1724;
        let v1726: f64 = v1615 * v15;
        let v1727: f64 = v60 * v1639;
        let v1728: f64 = v173 * v1633;
        let v1729: f64 = v1727 - v1728;
        let v1730: f64 = v68 * v1662;
        let v1731: f64 = v65 * v1670;
        let v1732: f64 = v1730 - v1731;
        let v1733: f64 = v1729 + v1732;
        let v1734: f64 = v28 * v1401;
        let v1735: f64 = v1733 - v1734;
        let v1736: f64 = v48 * v1709;
        let v1737: f64 = v40 * v1682;
        let v1738: f64 = v1736 - v1737;
        let v1739: f64 = v33 * v1738;
        let v1740: f64 = v262 * v1401;
        let v1741: f64 = v40 * v1709;
        let v1742: f64 = v48 * v1682;
        let v1743: f64 = v1741 + v1742;
        let v1744: f64 = v1740 + v1743;
        let v1745: f64 = v29 * v1744;
        let v1746: f64 = v1739 - v1745;
        let v1747: f64 = v1735 + v1746;
        let v1748: f64 = v18 * v1747;
        let v1749: f64 = v1726 + v1748;
        let v1750: f64 = v1725 - v1749;
        let v1751: f64 = v3 * v1750;
        let v1752: f64 = v1586 * v15;
        let v1753: f64 = v18 * v1722;
        let v1754: f64 = v1752 + v1753;
        (
            v1562,
            v1564,
            v1567,
            v1569,
            v1578,
            v1584,
            v1590,
            v1599,
            v1612,
            v1615,
            v1620,
            v1628,
            v1632,
            v1669,
            v1684,
            v1695,
            v1711,
            v1720,
            v1733,
            v1738,
            v1744,
            v1747,
            v1751,
            v1754,
        )
    };
    let (
        v1762,
        v1765,
        v1769,
        v1777,
        v1779,
        v1785,
        v1793,
        v1796,
        v1806,
        v1811,
        v1815,
        v1818,
        v1822,
        v1824,
        v1827,
        v1844,
        v1850,
        v1854,
        v1855,
        v1857,
        v1869,
        v1871,
        v1889,
        v1892,
        v1902,
        v1906,
        v1908,
        v1911,
        v1912,
        v1913,
        v1915,
        v1919,
        v1922,
        v1923,
        v1926,
        v1930,
        v1934,
        v1937,
        v1938,
        v1941,
        v1945,
        v1946,
        v1947,
        v1948,
        v1949,
    ) = {
        let v1755: f64 = v15 * v1747;
        let v1756: f64 = v1615 * v18;
        let v1757: f64 = v1755 - v1756;
        let v1758: f64 = v1754 + v1757;
        let v1759: f64 = v10 * v1738;
        let v1760: f64 = v1758 + v1759;
        let v1761: f64 = v6 * v1760;
        let v1762: f64 = v1751 + v1761;
        let v1763: f64 = v33 * v28;
        let v1764: f64 = v1763 - v1404;
        let v1765: f64 = v52 * v1411;
        let v1766: f64 = v33 * v60;
        let v1767: f64 = v1765 + v1766;
        let v1768: f64 = v1408 - v1767;
        let v1769: f64 = v33 * v65;
        let v1770: f64 = v68 * v1426;
        let v1771: f64 = v1769 + v1770;
        let v1772: f64 = v81 * v1771;
        let v1773: f64 = v91 * v1411;
        let v1774: f64 = v1772 - v1773;
        let v1775: f64 = v1423 + v1774;
        let v1776: f64 = v112 * v1771;
        let v1777: f64 = v33 * v68;
        let v1778: f64 = v65 * v1426;
        let v1779: f64 = v1777 - v1778;
        let v1780: f64 = v99 * v1779;
        let v1781: f64 = v96 * v1411;
        let v1782: f64 = v1780 - v1781;
        let v1783: f64 = v114 * v1782;
        let v1784: f64 = v1776 + v1783;
        let v1785: f64 = v1444 + v1784;
        let v1786: f64 = v96 * v1785;
        let v1787: f64 = v96 * v1779;
        let v1788: f64 = v99 * v1411;
        let v1789: f64 = v1787 + v1788;
        let v1790: f64 = v114 * v1789;
        let v1791: f64 = v136 * v1771;
        let v1792: f64 = v1790 - v1791;
        let v1793: f64 = v1460 + v1792;
        let v1794: f64 = v99 * v1793;
        let v1795: f64 = v1786 - v1794;
        let v1796: f64 = v1775 + v1795;
        let v1797: f64 = v65 * v1796;
        let v1798: f64 = v81 * v1779;
        let v1799: f64 = v151 * v1411;
        let v1800: f64 = v1798 - v1799;
        let v1801: f64 = v1476 - v1800;
        let v1802: f64 = v136 * v1782;
        let v1803: f64 = v112 * v1789;
        let v1804: f64 = v1802 + v1803;
        let v1805: f64 = v1485 - v1804;
        let v1806: f64 = v1801 + v1805;
        let v1807: f64 = v68 * v1806;
        let v1808: f64 = v1797 - v1807;
        let v1809: f64 = v1768 + v1808;
        let v1810: f64 = v170 * v1411;
        let v1811: f64 = v1810 + v1495;
        let v1812: f64 = v180 * v1411;
        let v1813: f64 = v1499 + v1812;
        let v1814: f64 = v183 * v1789;
        let v1815: f64 = v1814 - v1505;
        let v1816: f64 = v99 * v1815;
        let v1817: f64 = v183 * v1782;
        let v1818: f64 = v1510 - v1817;
        let v1819: f64 = v96 * v1818;
        let v1820: f64 = v1816 + v1819;
        let v1821: f64 = v1813 + v1820;
        let v1822: f64 = v1811 + v1821;
        let v1823: f64 = v10 * v1822;
        let v1824: f64 = v1809 - v1823;
        let v1825: f64 = v40 * v1824;
        let v1826: f64 = v33 * v173;
        let v1827: f64 = v52 * v1426;
        let v1828: f64 = v1826 + v1827;
        let v1829: f64 = v1522 + v1828;
        let v1830: f64 = v91 * v1779;
        let v1831: f64 = v151 * v1771;
        let v1832: f64 = v1830 - v1831;
        let v1833: f64 = v1531 + v1832;
        let v1834: f64 = v99 * v1785;
        let v1835: f64 = v96 * v1793;
        let v1836: f64 = v1834 + v1835;
        let v1837: f64 = v1833 + v1836;
        let v1838: f64 = v1829 - v1837;
        let v1839: f64 = v180 * v1779;
        let v1840: f64 = v1839 - v1547;
        let v1841: f64 = v96 * v1815;
        let v1842: f64 = v99 * v1818;
        let v1843: f64 = v1841 - v1842;
        let v1844: f64 = v1840 + v1843;
        let v1845: f64 = v65 * v1844;
        let v1846: f64 = v180 * v1771;
        let v1847: f64 = v1846 + v1557;
        let v1848: f64 = v183 * v1771;
        let v1849: f64 = v1848 + v1562;
        let v1850: f64 = v1847 + v1849;
        let v1851: f64 = v68 * v1850;
        let v1852: f64 = v1845 - v1851;
        let v1853: f64 = v170 * v1426;
        let v1854: f64 = v1853 + v1542;
        let v1855: f64 = v1852 - v1854;
        let v1856: f64 = v10 * v1855;
        let v1857: f64 = v1838 - v1856;
        let v1858: f64 = v48 * v1857;
        let v1859: f64 = v1825 + v1858;
        let v1860: f64 = v1764 + v1859;
        let v1861: f64 = v33 * v262;
        let v1862: f64 = v1861 + v283;
        let v1863: f64 = v33 * v170;
        let v1864: f64 = v1863 + v1578;
        let v1865: f64 = v68 * v1844;
        let v1866: f64 = v65 * v1850;
        let v1867: f64 = v1865 + v1866;
        let v1868: f64 = v1864 + v1867;
        let v1869: f64 = v1862 + v1868;
        let v1870: f64 = v29 * v1869;
        let v1871: f64 = v1860 + v1870;
        let v1872: f64 = v15 * v1871;
        let v1873: f64 = v173 * v1411;
        let v1874: f64 = v60 * v1426;
        let v1875: f64 = v1873 - v1874;
        let v1876: f64 = v1590 + v1875;
        let v1877: f64 = v68 * v1796;
        let v1878: f64 = v65 * v1806;
        let v1879: f64 = v1877 + v1878;
        let v1880: f64 = v1876 + v1879;
        let v1881: f64 = v1880 - v1599;
        let v1882: f64 = v48 * v1855;
        let v1883: f64 = v40 * v1822;
        let v1884: f64 = v1882 + v1883;
        let v1885: f64 = v33 * v1884;
        let v1886: f64 = v40 * v1855;
        let v1887: f64 = v48 * v1822;
        let v1888: f64 = v1886 - v1887;
        let v1889: f64 = v1888 - v32;
        let v1890: f64 = v29 * v1889;
        let v1891: f64 = v1885 - v1890;
        let v1892: f64 = v1881 + v1891;
        let v1893: f64 = v18 * v1892;
        let v1894: f64 = v1872 - v1893;
        let v1895: f64 = v1894 * v6;
        let v1896: f64 = v18 * v1871;
        let v1897: f64 = v15 * v1892;
        let v1898: f64 = v1896 + v1897;
        let v1899: f64 = v10 * v1884;
        let v1900: f64 = v1898 + v1899;
        let v1901: f64 = v1900 * v3;
        let v1902: f64 = v1895 - v1901;
        let v1903: f64 = v1762 + v1902;
        let v1904: f64 = v0 * v1903;
        let v1905: f64 = v1904 * v896;
        let v1906: f64 = v1632 + v1905;
        let v1907: f64 = v1409 * v40;
        let v1908: f64 = v1907 - v1426;
        let v1909: f64 = v52 * v1908;
        let v1910: f64 = v41 * v40;
        let v1911: f64 = v1521 + v1910;
        let v1912: f64 = v1909 - v1911;
        let v1913: f64 = v68 * v40;
        let v1914: f64 = v75 * v1913;
        let v1915: f64 = v65 * v40;
        let v1916: f64 = v66 * v1915;
        let v1917: f64 = v72 * v48;
        let v1918: f64 = v1916 - v1917;
        let v1919: f64 = v1914 - v1918;
        let v1920: f64 = v91 * v1908;
        let v1921: f64 = v1409 * v48;
        let v1922: f64 = v1411 - v1921;
        let v1923: f64 = v68 * v1922;
        let v1924: f64 = v81 * v1923;
        let v1925: f64 = v1920 - v1924;
        let v1926: f64 = v1919 + v1925;
        let v1927: f64 = v109 * v1913;
        let v1928: f64 = v96 * v1915;
        let v1929: f64 = v99 * v48;
        let v1930: f64 = v1928 - v1929;
        let v1931: f64 = v97 * v1930;
        let v1932: f64 = v96 * v48;
        let v1933: f64 = v99 * v1915;
        let v1934: f64 = v1932 + v1933;
        let v1935: f64 = v103 * v1934;
        let v1936: f64 = v1931 - v1935;
        let v1937: f64 = v1927 - v1936;
        let v1938: f64 = v65 * v1922;
        let v1939: f64 = v99 * v1938;
        let v1940: f64 = v96 * v1908;
        let v1941: f64 = v1939 + v1940;
        let v1942: f64 = v114 * v1941;
        let v1943: f64 = v112 * v1923;
        let v1944: f64 = v1942 - v1943;
        let v1945: f64 = v1937 + v1944;
        let v1946: f64 = v96 * v1945;
        let v1947: f64 = v129 * v1913;
        let v1948: f64 = v103 * v1930;
        let v1949: f64 = v126 * v1934;
        (
            v1762,
            v1765,
            v1769,
            v1777,
            v1779,
            v1785,
            v1793,
            v1796,
            v1806,
            v1811,
            v1815,
            v1818,
            v1822,
            v1824,
            v1827,
            v1844,
            v1850,
            v1854,
            v1855,
            v1857,
            v1869,
            v1871,
            v1889,
            v1892,
            v1902,
            v1906,
            v1908,
            v1911,
            v1912,
            v1913,
            v1915,
            v1919,
            v1922,
            v1923,
            v1926,
            v1930,
            v1934,
            v1937,
            v1938,
            v1941,
            v1945,
            v1946,
            v1947,
            v1948,
            v1949,
        )
    };
    let (
        v1951,
        v1967,
        v1976,
        v1980,
        v1989,
        v1995,
        v2000,
        v2008,
        v2014,
        v2021,
        v2029,
        v2036,
        v2046,
        v2051,
        v2058,
        v2064,
        v2068,
        v2077,
        v2082,
        v2097,
        v2110,
        v2112,
        v2114,
        v2116,
        v2120,
        v2126,
        v2129,
        v2131,
        v2137,
        v2139,
        v2142,
        v2143,
        v2144,
    ) = {
        let v1950: f64 = v1948 - v1949;
        let v1951: f64 = v1947 - v1950;
        let v1952: f64 = v96 * v1938;
        let v1953: f64 = v99 * v1908;
        let v1954: f64 = v1952 - v1953;
        let v1955: f64 = v114 * v1954;
        let v1956: f64 = v136 * v1923;
        let v1957: f64 = v1955 + v1956;
        let v1958: f64 = v1951 + v1957;
        let v1959: f64 = v99 * v1958;
        let v1960: f64 = v1946 - v1959;
        let v1961: f64 = v1926 + v1960;
        let v1962: f64 = v65 * v1961;
        let v1963: f64 = v148 * v1913;
        let v1964: f64 = v75 * v1915;
        let v1965: f64 = v145 * v48;
        let v1966: f64 = v1964 - v1965;
        let v1967: f64 = v1963 - v1966;
        let v1968: f64 = v151 * v1908;
        let v1969: f64 = v81 * v1938;
        let v1970: f64 = v1968 + v1969;
        let v1971: f64 = v1967 - v1970;
        let v1972: f64 = v159 * v1913;
        let v1973: f64 = v109 * v1930;
        let v1974: f64 = v129 * v1934;
        let v1975: f64 = v1973 - v1974;
        let v1976: f64 = v1972 - v1975;
        let v1977: f64 = v136 * v1941;
        let v1978: f64 = v112 * v1954;
        let v1979: f64 = v1977 + v1978;
        let v1980: f64 = v1976 - v1979;
        let v1981: f64 = v1971 + v1980;
        let v1982: f64 = v68 * v1981;
        let v1983: f64 = v1962 - v1982;
        let v1984: f64 = v1912 + v1983;
        let v1985: f64 = v170 * v1908;
        let v1986: f64 = v1985 - v1542;
        let v1987: f64 = v151 * v1913;
        let v1988: f64 = v91 * v1915;
        let v1989: f64 = v1987 + v1988;
        let v1990: f64 = v180 * v1908;
        let v1991: f64 = v1989 - v1990;
        let v1992: f64 = v183 * v1954;
        let v1993: f64 = v112 * v1913;
        let v1994: f64 = v114 * v1934;
        let v1995: f64 = v1993 - v1994;
        let v1996: f64 = v1992 - v1995;
        let v1997: f64 = v99 * v1996;
        let v1998: f64 = v136 * v1913;
        let v1999: f64 = v114 * v1930;
        let v2000: f64 = v1998 + v1999;
        let v2001: f64 = v183 * v1941;
        let v2002: f64 = v2000 - v2001;
        let v2003: f64 = v96 * v2002;
        let v2004: f64 = v1997 + v2003;
        let v2005: f64 = v1991 + v2004;
        let v2006: f64 = v1986 - v2005;
        let v2007: f64 = v10 * v2006;
        let v2008: f64 = v1984 + v2007;
        let v2009: f64 = v40 * v2008;
        let v2010: f64 = v1518 * v48;
        let v2011: f64 = v2009 - v2010;
        let v2012: f64 = v1569 * v40;
        let v2013: f64 = v206 * v48;
        let v2014: f64 = v2013 + v1406;
        let v2015: f64 = v52 * v1922;
        let v2016: f64 = v2014 + v2015;
        let v2017: f64 = v145 * v1913;
        let v2018: f64 = v72 * v1915;
        let v2019: f64 = v214 * v48;
        let v2020: f64 = v2018 - v2019;
        let v2021: f64 = v2017 - v2020;
        let v2022: f64 = v91 * v1938;
        let v2023: f64 = v151 * v1923;
        let v2024: f64 = v2022 + v2023;
        let v2025: f64 = v2021 + v2024;
        let v2026: f64 = v99 * v1945;
        let v2027: f64 = v96 * v1958;
        let v2028: f64 = v2026 + v2027;
        let v2029: f64 = v2025 + v2028;
        let v2030: f64 = v2016 + v2029;
        let v2031: f64 = v170 * v1922;
        let v2032: f64 = v2031 + v1495;
        let v2033: f64 = v180 * v1938;
        let v2034: f64 = v81 * v1913;
        let v2035: f64 = v91 * v48;
        let v2036: f64 = v2034 - v2035;
        let v2037: f64 = v2033 - v2036;
        let v2038: f64 = v96 * v1996;
        let v2039: f64 = v99 * v2002;
        let v2040: f64 = v2038 - v2039;
        let v2041: f64 = v2037 + v2040;
        let v2042: f64 = v65 * v2041;
        let v2043: f64 = v180 * v1923;
        let v2044: f64 = v151 * v48;
        let v2045: f64 = v81 * v1915;
        let v2046: f64 = v2044 + v2045;
        let v2047: f64 = v2043 + v2046;
        let v2048: f64 = v183 * v1923;
        let v2049: f64 = v136 * v1934;
        let v2050: f64 = v112 * v1930;
        let v2051: f64 = v2049 + v2050;
        let v2052: f64 = v2048 + v2051;
        let v2053: f64 = v2047 + v2052;
        let v2054: f64 = v68 * v2053;
        let v2055: f64 = v2042 + v2054;
        let v2056: f64 = v2032 + v2055;
        let v2057: f64 = v10 * v2056;
        let v2058: f64 = v2030 + v2057;
        let v2059: f64 = v48 * v2058;
        let v2060: f64 = v2012 - v2059;
        let v2061: f64 = v2011 + v2060;
        let v2062: f64 = v60 * v40;
        let v2063: f64 = v173 * v48;
        let v2064: f64 = v2062 - v2063;
        let v2065: f64 = v68 * v2041;
        let v2066: f64 = v65 * v2053;
        let v2067: f64 = v2065 - v2066;
        let v2068: f64 = v2064 + v2067;
        let v2069: f64 = v29 * v2068;
        let v2070: f64 = v2061 + v2069;
        let v2071: f64 = v15 * v2070;
        let v2072: f64 = v60 * v1922;
        let v2073: f64 = v173 * v1908;
        let v2074: f64 = v2072 - v2073;
        let v2075: f64 = v203 * v48;
        let v2076: f64 = v44 * v40;
        let v2077: f64 = v2075 + v2076;
        let v2078: f64 = v2074 - v2077;
        let v2079: f64 = v68 * v1961;
        let v2080: f64 = v65 * v1981;
        let v2081: f64 = v2079 + v2080;
        let v2082: f64 = v2078 + v2081;
        let v2083: f64 = v1567 * v40;
        let v2084: f64 = v48 * v2056;
        let v2085: f64 = v2083 + v2084;
        let v2086: f64 = v40 * v2006;
        let v2087: f64 = v1516 * v48;
        let v2088: f64 = v2086 - v2087;
        let v2089: f64 = v2085 - v2088;
        let v2090: f64 = v33 * v2089;
        let v2091: f64 = v40 * v2056;
        let v2092: f64 = v1567 * v48;
        let v2093: f64 = v2091 - v2092;
        let v2094: f64 = v1516 * v40;
        let v2095: f64 = v48 * v2006;
        let v2096: f64 = v2094 + v2095;
        let v2097: f64 = v2093 + v2096;
        let v2098: f64 = v29 * v2097;
        let v2099: f64 = v2090 - v2098;
        let v2100: f64 = v2082 + v2099;
        let v2101: f64 = v18 * v2100;
        let v2102: f64 = v2071 - v2101;
        let v2103: f64 = v3 * v2102;
        let v2104: f64 = v18 * v2070;
        let v2105: f64 = v15 * v2100;
        let v2106: f64 = v2104 + v2105;
        let v2107: f64 = v10 * v2089;
        let v2108: f64 = v2106 + v2107;
        let v2109: f64 = v6 * v2108;
        let v2110: f64 = v2103 + v2109;
        let v2111: f64 = v66 * v68;
        let v2112: f64 = v75 * v65;
        let v2113: f64 = v2111 + v2112;
        let v2114: f64 = v96 * v68;
        let v2115: f64 = v97 * v2114;
        let v2116: f64 = v99 * v68;
        let v2117: f64 = v103 * v2116;
        let v2118: f64 = v2115 - v2117;
        let v2119: f64 = v109 * v65;
        let v2120: f64 = v2118 + v2119;
        let v2121: f64 = v96 * v2120;
        let v2122: f64 = v103 * v2114;
        let v2123: f64 = v126 * v2116;
        let v2124: f64 = v2122 - v2123;
        let v2125: f64 = v129 * v65;
        let v2126: f64 = v2124 + v2125;
        let v2127: f64 = v99 * v2126;
        let v2128: f64 = v2121 - v2127;
        let v2129: f64 = v2113 + v2128;
        let v2130: f64 = v65 * v2129;
        let v2131: f64 = v75 * v68;
        let v2132: f64 = v148 * v65;
        let v2133: f64 = v2131 + v2132;
        let v2134: f64 = v109 * v2114;
        let v2135: f64 = v129 * v2116;
        let v2136: f64 = v2134 - v2135;
        let v2137: f64 = v159 * v65;
        let v2138: f64 = v2136 + v2137;
        let v2139: f64 = v2133 + v2138;
        let v2140: f64 = v68 * v2139;
        let v2141: f64 = v2130 - v2140;
        let v2142: f64 = v44 + v2141;
        let v2143: f64 = v151 * v65;
        let v2144: f64 = v91 * v68;
        (
            v1951,
            v1967,
            v1976,
            v1980,
            v1989,
            v1995,
            v2000,
            v2008,
            v2014,
            v2021,
            v2029,
            v2036,
            v2046,
            v2051,
            v2058,
            v2064,
            v2068,
            v2077,
            v2082,
            v2097,
            v2110,
            v2112,
            v2114,
            v2116,
            v2120,
            v2126,
            v2129,
            v2131,
            v2137,
            v2139,
            v2142,
            v2143,
            v2144,
        )
    };
    let (
        v2148,
        v2152,
        v2156,
        v2158,
        v2168,
        v2172,
        v2174,
        v2178,
        v2181,
        v2183,
        v2188,
        v2190,
        v2202,
        v2205,
        v2215,
        v2219,
        v2224,
        v2236,
        v2250,
        v2258,
        v2265,
        v2272,
        v2276,
        v2277,
        v2283,
        v2287,
        v2292,
        v2297,
        v2299,
        v2303,
        v2311,
        v2313,
        v2318,
        v2323,
        v2328,
        v2331,
        v2334,
        v2336,
        v2338,
        v2339,
    ) = {
        let v2145: f64 = v2143 - v2144;
        let v2146: f64 = v136 * v65;
        let v2147: f64 = v114 * v2114;
        let v2148: f64 = v2146 - v2147;
        let v2149: f64 = v96 * v2148;
        let v2150: f64 = v114 * v2116;
        let v2151: f64 = v112 * v65;
        let v2152: f64 = v2150 + v2151;
        let v2153: f64 = v99 * v2152;
        let v2154: f64 = v2149 - v2153;
        let v2155: f64 = v2145 + v2154;
        let v2156: f64 = v173 + v2155;
        let v2157: f64 = v10 * v2156;
        let v2158: f64 = v2142 - v2157;
        let v2159: f64 = v40 * v2158;
        let v2160: f64 = v72 * v68;
        let v2161: f64 = v145 * v65;
        let v2162: f64 = v2160 + v2161;
        let v2163: f64 = v99 * v2120;
        let v2164: f64 = v96 * v2126;
        let v2165: f64 = v2163 + v2164;
        let v2166: f64 = v2162 + v2165;
        let v2167: f64 = v203 - v2166;
        let v2168: f64 = v81 * v65;
        let v2169: f64 = v96 * v2152;
        let v2170: f64 = v99 * v2148;
        let v2171: f64 = v2169 + v2170;
        let v2172: f64 = v2168 + v2171;
        let v2173: f64 = v65 * v2172;
        let v2174: f64 = v81 * v68;
        let v2175: f64 = v112 * v2114;
        let v2176: f64 = v136 * v2116;
        let v2177: f64 = v2175 + v2176;
        let v2178: f64 = v2174 + v2177;
        let v2179: f64 = v68 * v2178;
        let v2180: f64 = v2173 + v2179;
        let v2181: f64 = v60 - v2180;
        let v2182: f64 = v10 * v2181;
        let v2183: f64 = v2167 - v2182;
        let v2184: f64 = v48 * v2183;
        let v2185: f64 = v2159 + v2184;
        let v2186: f64 = v65 * v2178;
        let v2187: f64 = v68 * v2172;
        let v2188: f64 = v2186 - v2187;
        let v2189: f64 = v29 * v2188;
        let v2190: f64 = v2185 + v2189;
        let v2191: f64 = v15 * v2190;
        let v2192: f64 = v68 * v2129;
        let v2193: f64 = v65 * v2139;
        let v2194: f64 = v2192 + v2193;
        let v2195: f64 = v289 + v2194;
        let v2196: f64 = v48 * v2181;
        let v2197: f64 = v40 * v2156;
        let v2198: f64 = v2196 + v2197;
        let v2199: f64 = v33 * v2198;
        let v2200: f64 = v40 * v2181;
        let v2201: f64 = v48 * v2156;
        let v2202: f64 = v2200 - v2201;
        let v2203: f64 = v29 * v2202;
        let v2204: f64 = v2199 - v2203;
        let v2205: f64 = v2195 + v2204;
        let v2206: f64 = v18 * v2205;
        let v2207: f64 = v2191 - v2206;
        let v2208: f64 = v2207 * v6;
        let v2209: f64 = v18 * v2190;
        let v2210: f64 = v15 * v2205;
        let v2211: f64 = v2209 + v2210;
        let v2212: f64 = v10 * v2198;
        let v2213: f64 = v2211 + v2212;
        let v2214: f64 = v2213 * v3;
        let v2215: f64 = v2208 - v2214;
        let v2216: f64 = v2110 + v2215;
        let v2217: f64 = v0 * v2216;
        let v2218: f64 = v2217 * v1116;
        let v2219: f64 = v1906 + v2218;
        let v2220: f64 = v48 * v65;
        let v2221: f64 = v75 * v2220;
        let v2222: f64 = v48 * v68;
        let v2223: f64 = v66 * v2222;
        let v2224: f64 = v2221 + v2223;
        let v2225: f64 = v1402 * v68;
        let v2226: f64 = v1427 * v65;
        let v2227: f64 = v2225 + v2226;
        let v2228: f64 = v81 * v2227;
        let v2229: f64 = v2224 - v2228;
        let v2230: f64 = v109 * v2220;
        let v2231: f64 = v99 * v2222;
        let v2232: f64 = v103 * v2231;
        let v2233: f64 = v96 * v2222;
        let v2234: f64 = v97 * v2233;
        let v2235: f64 = v2232 - v2234;
        let v2236: f64 = v2230 - v2235;
        let v2237: f64 = v1402 * v65;
        let v2238: f64 = v1427 * v68;
        let v2239: f64 = v2237 - v2238;
        let v2240: f64 = v99 * v2239;
        let v2241: f64 = v114 * v2240;
        let v2242: f64 = v112 * v2227;
        let v2243: f64 = v2241 - v2242;
        let v2244: f64 = v2236 + v2243;
        let v2245: f64 = v96 * v2244;
        let v2246: f64 = v129 * v2220;
        let v2247: f64 = v126 * v2231;
        let v2248: f64 = v103 * v2233;
        let v2249: f64 = v2247 - v2248;
        let v2250: f64 = v2246 - v2249;
        let v2251: f64 = v96 * v2239;
        let v2252: f64 = v114 * v2251;
        let v2253: f64 = v136 * v2227;
        let v2254: f64 = v2252 + v2253;
        let v2255: f64 = v2250 + v2254;
        let v2256: f64 = v99 * v2255;
        let v2257: f64 = v2245 - v2256;
        let v2258: f64 = v2229 + v2257;
        let v2259: f64 = v65 * v2258;
        let v2260: f64 = v1470 * v68;
        let v2261: f64 = v2259 - v2260;
        let v2262: f64 = v1490 * v65;
        let v2263: f64 = v148 * v2220;
        let v2264: f64 = v75 * v2222;
        let v2265: f64 = v2263 + v2264;
        let v2266: f64 = v81 * v2239;
        let v2267: f64 = v2265 - v2266;
        let v2268: f64 = v159 * v2220;
        let v2269: f64 = v129 * v2231;
        let v2270: f64 = v109 * v2233;
        let v2271: f64 = v2269 - v2270;
        let v2272: f64 = v2268 - v2271;
        let v2273: f64 = v136 * v2240;
        let v2274: f64 = v112 * v2251;
        let v2275: f64 = v2273 + v2274;
        let v2276: f64 = v2272 - v2275;
        let v2277: f64 = v2267 + v2276;
        let v2278: f64 = v68 * v2277;
        let v2279: f64 = v2262 + v2278;
        let v2280: f64 = v2261 - v2279;
        let v2281: f64 = v151 * v2220;
        let v2282: f64 = v91 * v2222;
        let v2283: f64 = v2281 - v2282;
        let v2284: f64 = v183 * v2251;
        let v2285: f64 = v114 * v2231;
        let v2286: f64 = v112 * v2220;
        let v2287: f64 = v2285 + v2286;
        let v2288: f64 = v2284 - v2287;
        let v2289: f64 = v99 * v2288;
        let v2290: f64 = v136 * v2220;
        let v2291: f64 = v114 * v2233;
        let v2292: f64 = v2290 - v2291;
        let v2293: f64 = v183 * v2240;
        let v2294: f64 = v2292 - v2293;
        let v2295: f64 = v96 * v2294;
        let v2296: f64 = v2289 + v2295;
        let v2297: f64 = v2283 + v2296;
        let v2298: f64 = v10 * v2297;
        let v2299: f64 = v2280 - v2298;
        let v2300: f64 = v40 * v2299;
        let v2301: f64 = v145 * v2220;
        let v2302: f64 = v72 * v2222;
        let v2303: f64 = v2301 + v2302;
        let v2304: f64 = v91 * v2239;
        let v2305: f64 = v151 * v2227;
        let v2306: f64 = v2304 + v2305;
        let v2307: f64 = v2303 + v2306;
        let v2308: f64 = v99 * v2244;
        let v2309: f64 = v96 * v2255;
        let v2310: f64 = v2308 + v2309;
        let v2311: f64 = v2307 + v2310;
        let v2312: f64 = v180 * v2239;
        let v2313: f64 = v81 * v2220;
        let v2314: f64 = v2312 - v2313;
        let v2315: f64 = v96 * v2288;
        let v2316: f64 = v99 * v2294;
        let v2317: f64 = v2315 - v2316;
        let v2318: f64 = v2314 + v2317;
        let v2319: f64 = v65 * v2318;
        let v2320: f64 = v1552 * v68;
        let v2321: f64 = v2319 - v2320;
        let v2322: f64 = v1564 * v65;
        let v2323: f64 = v81 * v2222;
        let v2324: f64 = v180 * v2227;
        let v2325: f64 = v2323 - v2324;
        let v2326: f64 = v136 * v2231;
        let v2327: f64 = v112 * v2233;
        let v2328: f64 = v2326 + v2327;
        let v2329: f64 = v183 * v2227;
        let v2330: f64 = v2328 - v2329;
        let v2331: f64 = v2325 + v2330;
        let v2332: f64 = v68 * v2331;
        let v2333: f64 = v2322 + v2332;
        let v2334: f64 = v2321 - v2333;
        let v2335: f64 = v10 * v2334;
        let v2336: f64 = v2311 + v2335;
        let v2337: f64 = v48 * v2336;
        let v2338: f64 = v2300 - v2337;
        let v2339: f64 = v1552 * v65;
        (
            v2148,
            v2152,
            v2156,
            v2158,
            v2168,
            v2172,
            v2174,
            v2178,
            v2181,
            v2183,
            v2188,
            v2190,
            v2202,
            v2205,
            v2215,
            v2219,
            v2224,
            v2236,
            v2250,
            v2258,
            v2265,
            v2272,
            v2276,
            v2277,
            v2283,
            v2287,
            v2292,
            v2297,
            v2299,
            v2303,
            v2311,
            v2313,
            v2318,
            v2323,
            v2328,
            v2331,
            v2334,
            v2336,
            v2338,
            v2339,
        )
    };
    let (
        v2345,
        v2355,
        v2362,
        v2375,
        v2376,
        v2378,
        v2381,
        v2382,
        v2385,
        v2389,
        v2390,
        v2393,
        v2394,
        v2395,
        v2396,
        v2397,
        v2399,
        v2405,
        v2406,
        v2408,
        v2412,
        v2413,
        v2415,
        v2417,
        v2422,
        v2424,
        v2435,
        v2438,
        v2448,
        v2452,
        v2465,
        v2473,
        v2481,
        v2485,
        v2489,
        v2493,
        v2498,
        v2504,
        v2506,
        v2514,
        v2526,
        v2527,
        v2529,
        v2531,
        v2533,
        v2534,
    ) = {
        let v2340: f64 = v68 * v2318;
        let v2341: f64 = v2339 + v2340;
        let v2342: f64 = v65 * v2331;
        let v2343: f64 = v1564 * v68;
        let v2344: f64 = v2342 - v2343;
        let v2345: f64 = v2341 + v2344;
        let v2346: f64 = v29 * v2345;
        let v2347: f64 = v2338 + v2346;
        let v2348: f64 = v15 * v2347;
        let v2349: f64 = v1470 * v65;
        let v2350: f64 = v68 * v2258;
        let v2351: f64 = v2349 + v2350;
        let v2352: f64 = v65 * v2277;
        let v2353: f64 = v1490 * v68;
        let v2354: f64 = v2352 - v2353;
        let v2355: f64 = v2351 + v2354;
        let v2356: f64 = v48 * v2334;
        let v2357: f64 = v40 * v2297;
        let v2358: f64 = v2356 + v2357;
        let v2359: f64 = v33 * v2358;
        let v2360: f64 = v40 * v2334;
        let v2361: f64 = v48 * v2297;
        let v2362: f64 = v2360 - v2361;
        let v2363: f64 = v29 * v2362;
        let v2364: f64 = v2359 - v2363;
        let v2365: f64 = v2355 + v2364;
        let v2366: f64 = v18 * v2365;
        let v2367: f64 = v2348 - v2366;
        let v2368: f64 = v3 * v2367;
        let v2369: f64 = v18 * v2347;
        let v2370: f64 = v15 * v2365;
        let v2371: f64 = v2369 + v2370;
        let v2372: f64 = v10 * v2358;
        let v2373: f64 = v2371 + v2372;
        let v2374: f64 = v6 * v2373;
        let v2375: f64 = v2368 + v2374;
        let v2376: f64 = v103 * v99;
        let v2377: f64 = v126 * v96;
        let v2378: f64 = v2376 + v2377;
        let v2379: f64 = v99 * v2378;
        let v2380: f64 = v97 * v99;
        let v2381: f64 = v103 * v96;
        let v2382: f64 = v2380 + v2381;
        let v2383: f64 = v96 * v2382;
        let v2384: f64 = v2379 - v2383;
        let v2385: f64 = v2384 - v72;
        let v2386: f64 = v65 * v2385;
        let v2387: f64 = v109 * v99;
        let v2388: f64 = v129 * v96;
        let v2389: f64 = v2387 + v2388;
        let v2390: f64 = v145 + v2389;
        let v2391: f64 = v68 * v2390;
        let v2392: f64 = v2386 + v2391;
        let v2393: f64 = v114 * v99;
        let v2394: f64 = v96 * v2393;
        let v2395: f64 = v114 * v96;
        let v2396: f64 = v99 * v2395;
        let v2397: f64 = v2394 - v2396;
        let v2398: f64 = v10 * v2397;
        let v2399: f64 = v2392 - v2398;
        let v2400: f64 = v40 * v2399;
        let v2401: f64 = v99 * v2382;
        let v2402: f64 = v96 * v2378;
        let v2403: f64 = v2401 + v2402;
        let v2404: f64 = v214 + v2403;
        let v2405: f64 = v96 * v2395;
        let v2406: f64 = v99 * v2393;
        let v2407: f64 = v2405 + v2406;
        let v2408: f64 = v91 + v2407;
        let v2409: f64 = v65 * v2408;
        let v2410: f64 = v136 * v96;
        let v2411: f64 = v112 * v99;
        let v2412: f64 = v2410 - v2411;
        let v2413: f64 = v151 + v2412;
        let v2414: f64 = v68 * v2413;
        let v2415: f64 = v2409 + v2414;
        let v2416: f64 = v10 * v2415;
        let v2417: f64 = v2404 + v2416;
        let v2418: f64 = v48 * v2417;
        let v2419: f64 = v2400 + v2418;
        let v2420: f64 = v65 * v2413;
        let v2421: f64 = v68 * v2408;
        let v2422: f64 = v2420 - v2421;
        let v2423: f64 = v29 * v2422;
        let v2424: f64 = v2419 + v2423;
        let v2425: f64 = v15 * v2424;
        let v2426: f64 = v68 * v2385;
        let v2427: f64 = v65 * v2390;
        let v2428: f64 = v2426 - v2427;
        let v2429: f64 = v40 * v2397;
        let v2430: f64 = v48 * v2415;
        let v2431: f64 = v2429 - v2430;
        let v2432: f64 = v33 * v2431;
        let v2433: f64 = v40 * v2415;
        let v2434: f64 = v48 * v2397;
        let v2435: f64 = v2433 + v2434;
        let v2436: f64 = v29 * v2435;
        let v2437: f64 = v2432 + v2436;
        let v2438: f64 = v2428 + v2437;
        let v2439: f64 = v18 * v2438;
        let v2440: f64 = v2425 - v2439;
        let v2441: f64 = v2440 * v6;
        let v2442: f64 = v18 * v2424;
        let v2443: f64 = v15 * v2438;
        let v2444: f64 = v2442 + v2443;
        let v2445: f64 = v10 * v2431;
        let v2446: f64 = v2444 + v2445;
        let v2447: f64 = v2446 * v3;
        let v2448: f64 = v2441 - v2447;
        let v2449: f64 = v2375 + v2448;
        let v2450: f64 = v0 * v2449;
        let v2451: f64 = v2450 * v1280;
        let v2452: f64 = v2219 + v2451;
        let v2453: f64 = v1448 * v96;
        let v2454: f64 = v1412 * v99;
        let v2455: f64 = v2453 - v2454;
        let v2456: f64 = v114 * v2455;
        let v2457: f64 = v40 * v96;
        let v2458: f64 = v1419 * v99;
        let v2459: f64 = v2457 - v2458;
        let v2460: f64 = v97 * v2459;
        let v2461: f64 = v40 * v99;
        let v2462: f64 = v1419 * v96;
        let v2463: f64 = v2461 + v2462;
        let v2464: f64 = v103 * v2463;
        let v2465: f64 = v2460 - v2464;
        let v2466: f64 = v2456 - v2465;
        let v2467: f64 = v96 * v2466;
        let v2468: f64 = v1454 * v99;
        let v2469: f64 = v2467 - v2468;
        let v2470: f64 = v1467 * v96;
        let v2471: f64 = v103 * v2459;
        let v2472: f64 = v126 * v2463;
        let v2473: f64 = v2471 - v2472;
        let v2474: f64 = v1448 * v99;
        let v2475: f64 = v1412 * v96;
        let v2476: f64 = v2474 + v2475;
        let v2477: f64 = v114 * v2476;
        let v2478: f64 = v2473 + v2477;
        let v2479: f64 = v99 * v2478;
        let v2480: f64 = v2470 - v2479;
        let v2481: f64 = v2469 - v2480;
        let v2482: f64 = v65 * v2481;
        let v2483: f64 = v109 * v2459;
        let v2484: f64 = v129 * v2463;
        let v2485: f64 = v2483 - v2484;
        let v2486: f64 = v136 * v2455;
        let v2487: f64 = v112 * v2476;
        let v2488: f64 = v2486 - v2487;
        let v2489: f64 = v2485 + v2488;
        let v2490: f64 = v68 * v2489;
        let v2491: f64 = v2482 + v2490;
        let v2492: f64 = v1506 * v96;
        let v2493: f64 = v114 * v2463;
        let v2494: f64 = v183 * v2476;
        let v2495: f64 = v2493 - v2494;
        let v2496: f64 = v99 * v2495;
        let v2497: f64 = v2492 + v2496;
        let v2498: f64 = v114 * v2459;
        let v2499: f64 = v183 * v2455;
        let v2500: f64 = v2498 - v2499;
        let v2501: f64 = v96 * v2500;
        let v2502: f64 = v1512 * v99;
        let v2503: f64 = v2501 - v2502;
        let v2504: f64 = v2497 + v2503;
        let v2505: f64 = v10 * v2504;
        let v2506: f64 = v2491 - v2505;
        let v2507: f64 = v40 * v2506;
        let v2508: f64 = v1454 * v96;
        let v2509: f64 = v99 * v2466;
        let v2510: f64 = v2508 + v2509;
        let v2511: f64 = v1467 * v99;
        let v2512: f64 = v96 * v2478;
        let v2513: f64 = v2511 + v2512;
        let v2514: f64 = v2510 - v2513;
        let v2515: f64 = v96 * v2495;
        let v2516: f64 = v1506 * v99;
        let v2517: f64 = v2515 - v2516;
        let v2518: f64 = v1512 * v96;
        let v2519: f64 = v99 * v2500;
        let v2520: f64 = v2518 + v2519;
        let v2521: f64 = v2517 - v2520;
        let v2522: f64 = v65 * v2521;
        let v2523: f64 = v136 * v2463;
        let v2524: f64 = v112 * v2459;
        let v2525: f64 = v2523 + v2524;
        let v2526: f64 = v68 * v2525;
        let v2527: f64 = v2522 + v2526;
        let v2528: f64 = v10 * v2527;
        let v2529: f64 = v2514 + v2528;
        let v2530: f64 = v48 * v2529;
        let v2531: f64 = v2507 - v2530;
        let v2532: f64 = v68 * v2521;
        let v2533: f64 = v65 * v2525;
        let v2534: f64 = v2532 - v2533;
        (
            v2345,
            v2355,
            v2362,
            v2375,
            v2376,
            v2378,
            v2381,
            v2382,
            v2385,
            v2389,
            v2390,
            v2393,
            v2394,
            v2395,
            v2396,
            v2397,
            v2399,
            v2405,
            v2406,
            v2408,
            v2412,
            v2413,
            v2415,
            v2417,
            v2422,
            v2424,
            v2435,
            v2438,
            v2448,
            v2452,
            v2465,
            v2473,
            v2481,
            v2485,
            v2489,
            v2493,
            v2498,
            v2504,
            v2506,
            v2514,
            v2526,
            v2527,
            v2529,
            v2531,
            v2533,
            v2534,
        )
    };
    let (
        v2540,
        v2547,
        v2560,
        v2563,
        v2569,
        v2571,
        v2575,
        v2576,
        v2581,
        v2584,
        v2586,
        v2597,
        v2600,
        v2610,
        v2614,
        v2615,
        v2628,
        v2632,
        v2665,
        v2666,
        v2681,
        v2683,
        v2696,
        v2712,
        v2714,
        v2721,
        v2723,
        v2724,
        v2728,
        v2729,
    ) = {
        let v2535: f64 = v29 * v2534;
        let v2536: f64 = v2531 + v2535;
        let v2537: f64 = v15 * v2536;
        let v2538: f64 = v68 * v2481;
        let v2539: f64 = v65 * v2489;
        let v2540: f64 = v2538 - v2539;
        let v2541: f64 = v48 * v2527;
        let v2542: f64 = v40 * v2504;
        let v2543: f64 = v2541 + v2542;
        let v2544: f64 = v33 * v2543;
        let v2545: f64 = v40 * v2527;
        let v2546: f64 = v48 * v2504;
        let v2547: f64 = v2545 - v2546;
        let v2548: f64 = v29 * v2547;
        let v2549: f64 = v2544 - v2548;
        let v2550: f64 = v2540 + v2549;
        let v2551: f64 = v18 * v2550;
        let v2552: f64 = v2537 - v2551;
        let v2553: f64 = v3 * v2552;
        let v2554: f64 = v18 * v2536;
        let v2555: f64 = v15 * v2550;
        let v2556: f64 = v2554 + v2555;
        let v2557: f64 = v10 * v2543;
        let v2558: f64 = v2556 + v2557;
        let v2559: f64 = v6 * v2558;
        let v2560: f64 = v2553 + v2559;
        let v2561: f64 = v96 * v109;
        let v2562: f64 = v99 * v129;
        let v2563: f64 = v2561 - v2562;
        let v2564: f64 = v65 * v2563;
        let v2565: f64 = v68 * v159;
        let v2566: f64 = v2564 - v2565;
        let v2567: f64 = v96 * v136;
        let v2568: f64 = v99 * v112;
        let v2569: f64 = v2567 - v2568;
        let v2570: f64 = v10 * v2569;
        let v2571: f64 = v2566 - v2570;
        let v2572: f64 = v40 * v2571;
        let v2573: f64 = v96 * v112;
        let v2574: f64 = v99 * v136;
        let v2575: f64 = v2573 + v2574;
        let v2576: f64 = v65 * v2575;
        let v2577: f64 = v10 * v2576;
        let v2578: f64 = v99 * v109;
        let v2579: f64 = v96 * v129;
        let v2580: f64 = v2578 + v2579;
        let v2581: f64 = v2577 - v2580;
        let v2582: f64 = v48 * v2581;
        let v2583: f64 = v2572 + v2582;
        let v2584: f64 = v68 * v2575;
        let v2585: f64 = v29 * v2584;
        let v2586: f64 = v2583 - v2585;
        let v2587: f64 = v15 * v2586;
        let v2588: f64 = v68 * v2563;
        let v2589: f64 = v65 * v159;
        let v2590: f64 = v2588 + v2589;
        let v2591: f64 = v40 * v2569;
        let v2592: f64 = v48 * v2576;
        let v2593: f64 = v2591 - v2592;
        let v2594: f64 = v33 * v2593;
        let v2595: f64 = v40 * v2576;
        let v2596: f64 = v48 * v2569;
        let v2597: f64 = v2595 + v2596;
        let v2598: f64 = v29 * v2597;
        let v2599: f64 = v2594 + v2598;
        let v2600: f64 = v2590 + v2599;
        let v2601: f64 = v18 * v2600;
        let v2602: f64 = v2587 - v2601;
        let v2603: f64 = v2602 * v6;
        let v2604: f64 = v18 * v2586;
        let v2605: f64 = v15 * v2600;
        let v2606: f64 = v2604 + v2605;
        let v2607: f64 = v10 * v2593;
        let v2608: f64 = v2606 + v2607;
        let v2609: f64 = v2608 * v3;
        let v2610: f64 = v2603 - v2609;
        let v2611: f64 = v2560 + v2610;
        let v2612: f64 = v0 * v2611;
        let v2613: f64 = v2612 * v1392;
        let v2614: f64 = v2452 + v2613;
        let v2615: f64 = v895 * v1395;
        let v2616: f64 = v1902 + v1762;
        let v2617: f64 = v0 * v2616;
        let v2618: f64 = v2617 * v618;
        let v2619: f64 = v2615 + v2618;
        let v2620: f64 = v1871 * v15;
        let v2621: f64 = v1892 * v18;
        let v2622: f64 = v2620 - v2621;
        let v2623: f64 = v6 * v2622;
        let v2624: f64 = v1871 * v18;
        let v2625: f64 = v1892 * v15;
        let v2626: f64 = v2624 + v2625;
        let v2627: f64 = v3 * v2626;
        let v2628: f64 = v2623 - v2627;
        let v2629: f64 = v2628 + v2628;
        let v2630: f64 = v0 * v2629;
        let v2631: f64 = v2630 * v896;
        let v2632: f64 = v2619 + v2631;
        let v2633: f64 = v68 * v1411;
        let v2634: f64 = v81 * v2633;
        let v2635: f64 = v91 * v1426;
        let v2636: f64 = v2634 + v2635;
        let v2637: f64 = v1919 - v2636;
        let v2638: f64 = v65 * v1411;
        let v2639: f64 = v99 * v2638;
        let v2640: f64 = v96 * v1426;
        let v2641: f64 = v2639 - v2640;
        let v2642: f64 = v114 * v2641;
        let v2643: f64 = v112 * v2633;
        let v2644: f64 = v2642 - v2643;
        let v2645: f64 = v1937 + v2644;
        let v2646: f64 = v96 * v2645;
        let v2647: f64 = v96 * v2638;
        let v2648: f64 = v99 * v1426;
        let v2649: f64 = v2647 + v2648;
        let v2650: f64 = v114 * v2649;
        let v2651: f64 = v136 * v2633;
        let v2652: f64 = v2650 + v2651;
        let v2653: f64 = v1951 + v2652;
        let v2654: f64 = v99 * v2653;
        let v2655: f64 = v2646 - v2654;
        let v2656: f64 = v2637 + v2655;
        let v2657: f64 = v65 * v2656;
        let v2658: f64 = v81 * v2638;
        let v2659: f64 = v151 * v1426;
        let v2660: f64 = v2658 - v2659;
        let v2661: f64 = v1967 - v2660;
        let v2662: f64 = v136 * v2641;
        let v2663: f64 = v112 * v2649;
        let v2664: f64 = v2662 + v2663;
        let v2665: f64 = v1976 - v2664;
        let v2666: f64 = v2661 + v2665;
        let v2667: f64 = v68 * v2666;
        let v2668: f64 = v2657 - v2667;
        let v2669: f64 = v1911 + v1827;
        let v2670: f64 = v2668 - v2669;
        let v2671: f64 = v180 * v1426;
        let v2672: f64 = v1989 + v2671;
        let v2673: f64 = v183 * v2649;
        let v2674: f64 = v2673 - v1995;
        let v2675: f64 = v99 * v2674;
        let v2676: f64 = v183 * v2641;
        let v2677: f64 = v2000 - v2676;
        let v2678: f64 = v96 * v2677;
        let v2679: f64 = v2675 + v2678;
        let v2680: f64 = v2672 + v2679;
        let v2681: f64 = v1854 + v2680;
        let v2682: f64 = v10 * v2681;
        let v2683: f64 = v2670 - v2682;
        let v2684: f64 = v40 * v2683;
        let v2685: f64 = v1824 * v48;
        let v2686: f64 = v2684 - v2685;
        let v2687: f64 = v1857 * v40;
        let v2688: f64 = v2014 + v1765;
        let v2689: f64 = v91 * v2638;
        let v2690: f64 = v151 * v2633;
        let v2691: f64 = v2689 + v2690;
        let v2692: f64 = v2021 + v2691;
        let v2693: f64 = v99 * v2645;
        let v2694: f64 = v96 * v2653;
        let v2695: f64 = v2693 + v2694;
        let v2696: f64 = v2692 + v2695;
        let v2697: f64 = v2688 + v2696;
        let v2698: f64 = v180 * v2638;
        let v2699: f64 = v2698 - v2036;
        let v2700: f64 = v96 * v2674;
        let v2701: f64 = v99 * v2677;
        let v2702: f64 = v2700 - v2701;
        let v2703: f64 = v2699 + v2702;
        let v2704: f64 = v65 * v2703;
        let v2705: f64 = v180 * v2633;
        let v2706: f64 = v2705 + v2046;
        let v2707: f64 = v183 * v2633;
        let v2708: f64 = v2707 + v2051;
        let v2709: f64 = v2706 + v2708;
        let v2710: f64 = v68 * v2709;
        let v2711: f64 = v2704 + v2710;
        let v2712: f64 = v2711 + v1811;
        let v2713: f64 = v10 * v2712;
        let v2714: f64 = v2697 + v2713;
        let v2715: f64 = v48 * v2714;
        let v2716: f64 = v2687 - v2715;
        let v2717: f64 = v2686 + v2716;
        let v2718: f64 = v68 * v2703;
        let v2719: f64 = v65 * v2709;
        let v2720: f64 = v2718 - v2719;
        let v2721: f64 = v2064 + v2720;
        let v2722: f64 = v29 * v2721;
        let v2723: f64 = v2717 + v2722;
        let v2724: f64 = v15 * v2723;
        let v2725: f64 = v173 * v1426;
        let v2726: f64 = v60 * v1411;
        let v2727: f64 = v2725 + v2726;
        let v2728: f64 = v2727 - v2077;
        let v2729: f64 = v68 * v2656;
        (
            v2540,
            v2547,
            v2560,
            v2563,
            v2569,
            v2571,
            v2575,
            v2576,
            v2581,
            v2584,
            v2586,
            v2597,
            v2600,
            v2610,
            v2614,
            v2615,
            v2628,
            v2632,
            v2665,
            v2666,
            v2681,
            v2683,
            v2696,
            v2712,
            v2714,
            v2721,
            v2723,
            v2724,
            v2728,
            v2729,
        )
    };
    let (
        v2732,
        v2747,
        v2760,
        v2769,
        v2803,
        v2817,
        v2826,
        v2846,
        v2855,
        v2865,
        v2872,
        v2885,
        v2894,
        v2898,
        v2901,
        v2903,
        v2912,
        v2915,
        v2920,
        v2922,
        v2923,
        v2924,
    ) = {
        let v2730: f64 = v65 * v2666;
        let v2731: f64 = v2729 + v2730;
        let v2732: f64 = v2728 + v2731;
        let v2733: f64 = v1855 * v40;
        let v2734: f64 = v48 * v2712;
        let v2735: f64 = v2733 + v2734;
        let v2736: f64 = v40 * v2681;
        let v2737: f64 = v1822 * v48;
        let v2738: f64 = v2736 - v2737;
        let v2739: f64 = v2735 + v2738;
        let v2740: f64 = v33 * v2739;
        let v2741: f64 = v40 * v2712;
        let v2742: f64 = v1855 * v48;
        let v2743: f64 = v2741 - v2742;
        let v2744: f64 = v1822 * v40;
        let v2745: f64 = v48 * v2681;
        let v2746: f64 = v2744 + v2745;
        let v2747: f64 = v2743 - v2746;
        let v2748: f64 = v29 * v2747;
        let v2749: f64 = v2740 - v2748;
        let v2750: f64 = v2732 + v2749;
        let v2751: f64 = v18 * v2750;
        let v2752: f64 = v2724 - v2751;
        let v2753: f64 = v3 * v2752;
        let v2754: f64 = v18 * v2723;
        let v2755: f64 = v15 * v2750;
        let v2756: f64 = v2754 + v2755;
        let v2757: f64 = v10 * v2739;
        let v2758: f64 = v2756 + v2757;
        let v2759: f64 = v6 * v2758;
        let v2760: f64 = v2753 + v2759;
        let v2761: f64 = v2190 * v15;
        let v2762: f64 = v2205 * v18;
        let v2763: f64 = v2761 - v2762;
        let v2764: f64 = v6 * v2763;
        let v2765: f64 = v2190 * v18;
        let v2766: f64 = v2205 * v15;
        let v2767: f64 = v2765 + v2766;
        let v2768: f64 = v3 * v2767;
        let v2769: f64 = v2764 - v2768;
        let v2770: f64 = v2760 + v2769;
        let v2771: f64 = v0 * v2770;
        let v2772: f64 = v2771 * v1116;
        let v2773: f64 = v2632 + v2772;
        let v2774: f64 = v1426 * v65;
        let v2775: f64 = v2774 - v1777;
        let v2776: f64 = v81 * v2775;
        let v2777: f64 = v2224 + v2776;
        let v2778: f64 = v112 * v2775;
        let v2779: f64 = v1426 * v68;
        let v2780: f64 = v1769 + v2779;
        let v2781: f64 = v99 * v2780;
        let v2782: f64 = v114 * v2781;
        let v2783: f64 = v2778 + v2782;
        let v2784: f64 = v2236 + v2783;
        let v2785: f64 = v96 * v2784;
        let v2786: f64 = v96 * v2780;
        let v2787: f64 = v114 * v2786;
        let v2788: f64 = v136 * v2775;
        let v2789: f64 = v2787 - v2788;
        let v2790: f64 = v2250 + v2789;
        let v2791: f64 = v99 * v2790;
        let v2792: f64 = v2785 - v2791;
        let v2793: f64 = v2777 + v2792;
        let v2794: f64 = v65 * v2793;
        let v2795: f64 = v1796 * v68;
        let v2796: f64 = v2794 - v2795;
        let v2797: f64 = v1806 * v65;
        let v2798: f64 = v81 * v2780;
        let v2799: f64 = v2265 - v2798;
        let v2800: f64 = v136 * v2781;
        let v2801: f64 = v112 * v2786;
        let v2802: f64 = v2800 + v2801;
        let v2803: f64 = v2272 - v2802;
        let v2804: f64 = v2799 + v2803;
        let v2805: f64 = v68 * v2804;
        let v2806: f64 = v2797 + v2805;
        let v2807: f64 = v2796 - v2806;
        let v2808: f64 = v183 * v2786;
        let v2809: f64 = v2808 - v2287;
        let v2810: f64 = v99 * v2809;
        let v2811: f64 = v183 * v2781;
        let v2812: f64 = v2292 - v2811;
        let v2813: f64 = v96 * v2812;
        let v2814: f64 = v2810 + v2813;
        let v2815: f64 = v2283 + v2814;
        let v2816: f64 = v10 * v2815;
        let v2817: f64 = v2807 - v2816;
        let v2818: f64 = v40 * v2817;
        let v2819: f64 = v91 * v2780;
        let v2820: f64 = v151 * v2775;
        let v2821: f64 = v2819 - v2820;
        let v2822: f64 = v2303 + v2821;
        let v2823: f64 = v99 * v2784;
        let v2824: f64 = v96 * v2790;
        let v2825: f64 = v2823 + v2824;
        let v2826: f64 = v2822 + v2825;
        let v2827: f64 = v180 * v2780;
        let v2828: f64 = v2827 - v2313;
        let v2829: f64 = v96 * v2809;
        let v2830: f64 = v99 * v2812;
        let v2831: f64 = v2829 - v2830;
        let v2832: f64 = v2828 + v2831;
        let v2833: f64 = v65 * v2832;
        let v2834: f64 = v1844 * v68;
        let v2835: f64 = v2833 - v2834;
        let v2836: f64 = v1850 * v65;
        let v2837: f64 = v180 * v2775;
        let v2838: f64 = v2837 + v2323;
        let v2839: f64 = v183 * v2775;
        let v2840: f64 = v2839 + v2328;
        let v2841: f64 = v2838 + v2840;
        let v2842: f64 = v68 * v2841;
        let v2843: f64 = v2836 + v2842;
        let v2844: f64 = v2835 - v2843;
        let v2845: f64 = v10 * v2844;
        let v2846: f64 = v2826 + v2845;
        let v2847: f64 = v48 * v2846;
        let v2848: f64 = v2818 - v2847;
        let v2849: f64 = v1844 * v65;
        let v2850: f64 = v68 * v2832;
        let v2851: f64 = v2849 + v2850;
        let v2852: f64 = v65 * v2841;
        let v2853: f64 = v1850 * v68;
        let v2854: f64 = v2852 - v2853;
        let v2855: f64 = v2851 + v2854;
        let v2856: f64 = v29 * v2855;
        let v2857: f64 = v2848 + v2856;
        let v2858: f64 = v15 * v2857;
        let v2859: f64 = v1796 * v65;
        let v2860: f64 = v68 * v2793;
        let v2861: f64 = v2859 + v2860;
        let v2862: f64 = v65 * v2804;
        let v2863: f64 = v1806 * v68;
        let v2864: f64 = v2862 - v2863;
        let v2865: f64 = v2861 + v2864;
        let v2866: f64 = v48 * v2844;
        let v2867: f64 = v40 * v2815;
        let v2868: f64 = v2866 + v2867;
        let v2869: f64 = v33 * v2868;
        let v2870: f64 = v40 * v2844;
        let v2871: f64 = v48 * v2815;
        let v2872: f64 = v2870 - v2871;
        let v2873: f64 = v29 * v2872;
        let v2874: f64 = v2869 - v2873;
        let v2875: f64 = v2865 + v2874;
        let v2876: f64 = v18 * v2875;
        let v2877: f64 = v2858 - v2876;
        let v2878: f64 = v3 * v2877;
        let v2879: f64 = v18 * v2857;
        let v2880: f64 = v15 * v2875;
        let v2881: f64 = v2879 + v2880;
        let v2882: f64 = v10 * v2868;
        let v2883: f64 = v2881 + v2882;
        let v2884: f64 = v6 * v2883;
        let v2885: f64 = v2878 + v2884;
        let v2886: f64 = v2424 * v15;
        let v2887: f64 = v2438 * v18;
        let v2888: f64 = v2886 - v2887;
        let v2889: f64 = v6 * v2888;
        let v2890: f64 = v2424 * v18;
        let v2891: f64 = v2438 * v15;
        let v2892: f64 = v2890 + v2891;
        let v2893: f64 = v3 * v2892;
        let v2894: f64 = v2889 - v2893;
        let v2895: f64 = v2885 + v2894;
        let v2896: f64 = v0 * v2895;
        let v2897: f64 = v2896 * v1280;
        let v2898: f64 = v2773 + v2897;
        let v2899: f64 = v1779 * v96;
        let v2900: f64 = v1411 * v99;
        let v2901: f64 = v2899 + v2900;
        let v2902: f64 = v114 * v2901;
        let v2903: f64 = v2902 - v2465;
        let v2904: f64 = v96 * v2903;
        let v2905: f64 = v1785 * v99;
        let v2906: f64 = v2904 - v2905;
        let v2907: f64 = v1793 * v96;
        let v2908: f64 = v1411 * v96;
        let v2909: f64 = v1779 * v99;
        let v2910: f64 = v2908 - v2909;
        let v2911: f64 = v114 * v2910;
        let v2912: f64 = v2911 - v2473;
        let v2913: f64 = v99 * v2912;
        let v2914: f64 = v2907 + v2913;
        let v2915: f64 = v2906 - v2914;
        let v2916: f64 = v65 * v2915;
        let v2917: f64 = v136 * v2901;
        let v2918: f64 = v112 * v2910;
        let v2919: f64 = v2917 + v2918;
        let v2920: f64 = v2485 + v2919;
        let v2921: f64 = v68 * v2920;
        let v2922: f64 = v2916 + v2921;
        let v2923: f64 = v1815 * v96;
        let v2924: f64 = v183 * v2910;
        (
            v2732,
            v2747,
            v2760,
            v2769,
            v2803,
            v2817,
            v2826,
            v2846,
            v2855,
            v2865,
            v2872,
            v2885,
            v2894,
            v2898,
            v2901,
            v2903,
            v2912,
            v2915,
            v2920,
            v2922,
            v2923,
            v2924,
        )
    };
    let (
        v2935,
        v2943,
        v2954,
        v2958,
        v2964,
        v2971,
        v2984,
        v2993,
        v2997,
        v2998,
        v3017,
        v3029,
        v3033,
        v3051,
        v3061,
        v3062,
        v3063,
        v3079,
        v3081,
        v3097,
        v3105,
        v3106,
        v3115,
        v3117,
        v3118,
        v3119,
    ) = {
        let v2925: f64 = v2924 + v2493;
        let v2926: f64 = v99 * v2925;
        let v2927: f64 = v2923 + v2926;
        let v2928: f64 = v183 * v2901;
        let v2929: f64 = v2498 - v2928;
        let v2930: f64 = v96 * v2929;
        let v2931: f64 = v1818 * v99;
        let v2932: f64 = v2930 - v2931;
        let v2933: f64 = v2927 + v2932;
        let v2934: f64 = v10 * v2933;
        let v2935: f64 = v2922 - v2934;
        let v2936: f64 = v40 * v2935;
        let v2937: f64 = v1785 * v96;
        let v2938: f64 = v99 * v2903;
        let v2939: f64 = v2937 + v2938;
        let v2940: f64 = v96 * v2912;
        let v2941: f64 = v1793 * v99;
        let v2942: f64 = v2940 - v2941;
        let v2943: f64 = v2939 + v2942;
        let v2944: f64 = v96 * v2925;
        let v2945: f64 = v1815 * v99;
        let v2946: f64 = v2944 - v2945;
        let v2947: f64 = v1818 * v96;
        let v2948: f64 = v99 * v2929;
        let v2949: f64 = v2947 + v2948;
        let v2950: f64 = v2946 - v2949;
        let v2951: f64 = v65 * v2950;
        let v2952: f64 = v2951 + v2526;
        let v2953: f64 = v10 * v2952;
        let v2954: f64 = v2943 + v2953;
        let v2955: f64 = v48 * v2954;
        let v2956: f64 = v2936 - v2955;
        let v2957: f64 = v68 * v2950;
        let v2958: f64 = v2957 - v2533;
        let v2959: f64 = v29 * v2958;
        let v2960: f64 = v2956 + v2959;
        let v2961: f64 = v15 * v2960;
        let v2962: f64 = v68 * v2915;
        let v2963: f64 = v65 * v2920;
        let v2964: f64 = v2962 - v2963;
        let v2965: f64 = v48 * v2952;
        let v2966: f64 = v40 * v2933;
        let v2967: f64 = v2965 + v2966;
        let v2968: f64 = v33 * v2967;
        let v2969: f64 = v40 * v2952;
        let v2970: f64 = v48 * v2933;
        let v2971: f64 = v2969 - v2970;
        let v2972: f64 = v29 * v2971;
        let v2973: f64 = v2968 - v2972;
        let v2974: f64 = v2964 + v2973;
        let v2975: f64 = v18 * v2974;
        let v2976: f64 = v2961 - v2975;
        let v2977: f64 = v3 * v2976;
        let v2978: f64 = v18 * v2960;
        let v2979: f64 = v15 * v2974;
        let v2980: f64 = v2978 + v2979;
        let v2981: f64 = v10 * v2967;
        let v2982: f64 = v2980 + v2981;
        let v2983: f64 = v6 * v2982;
        let v2984: f64 = v2977 + v2983;
        let v2985: f64 = v2586 * v15;
        let v2986: f64 = v2600 * v18;
        let v2987: f64 = v2985 - v2986;
        let v2988: f64 = v6 * v2987;
        let v2989: f64 = v2586 * v18;
        let v2990: f64 = v2600 * v15;
        let v2991: f64 = v2989 + v2990;
        let v2992: f64 = v3 * v2991;
        let v2993: f64 = v2988 - v2992;
        let v2994: f64 = v2984 + v2993;
        let v2995: f64 = v0 * v2994;
        let v2996: f64 = v2995 * v1392;
        let v2997: f64 = v2898 + v2996;
        let v2998: f64 = v1115 * v1395;
        let v2999: f64 = v2215 + v2110;
        let v3000: f64 = v0 * v2999;
        let v3001: f64 = v3000 * v618;
        let v3002: f64 = v2998 + v3001;
        let v3003: f64 = v2769 + v2760;
        let v3004: f64 = v0 * v3003;
        let v3005: f64 = v3004 * v896;
        let v3006: f64 = v3002 + v3005;
        let v3007: f64 = v2183 * v40;
        let v3008: f64 = v2158 * v48;
        let v3009: f64 = v3007 - v3008;
        let v3010: f64 = v15 * v3009;
        let v3011: f64 = v2181 * v40;
        let v3012: f64 = v2156 * v48;
        let v3013: f64 = v3011 - v3012;
        let v3014: f64 = v33 * v3013;
        let v3015: f64 = v2181 * v48;
        let v3016: f64 = v2156 * v40;
        let v3017: f64 = v3015 + v3016;
        let v3018: f64 = v29 * v3017;
        let v3019: f64 = v3014 + v3018;
        let v3020: f64 = v18 * v3019;
        let v3021: f64 = v3010 - v3020;
        let v3022: f64 = v3 * v3021;
        let v3023: f64 = v18 * v3009;
        let v3024: f64 = v15 * v3019;
        let v3025: f64 = v3023 + v3024;
        let v3026: f64 = v10 * v3013;
        let v3027: f64 = v3025 + v3026;
        let v3028: f64 = v6 * v3027;
        let v3029: f64 = v3022 + v3028;
        let v3030: f64 = v3029 + v3029;
        let v3031: f64 = v0 * v3030;
        let v3032: f64 = v3031 * v1116;
        let v3033: f64 = v3006 + v3032;
        let v3034: f64 = v66 * v65;
        let v3035: f64 = v3034 - v2131;
        let v3036: f64 = v96 * v65;
        let v3037: f64 = v97 * v3036;
        let v3038: f64 = v99 * v65;
        let v3039: f64 = v103 * v3038;
        let v3040: f64 = v3037 - v3039;
        let v3041: f64 = v109 * v68;
        let v3042: f64 = v3040 - v3041;
        let v3043: f64 = v96 * v3042;
        let v3044: f64 = v103 * v3036;
        let v3045: f64 = v126 * v3038;
        let v3046: f64 = v3044 - v3045;
        let v3047: f64 = v129 * v68;
        let v3048: f64 = v3046 - v3047;
        let v3049: f64 = v99 * v3048;
        let v3050: f64 = v3043 - v3049;
        let v3051: f64 = v3035 + v3050;
        let v3052: f64 = v65 * v3051;
        let v3053: f64 = v2129 * v68;
        let v3054: f64 = v3052 - v3053;
        let v3055: f64 = v2139 * v65;
        let v3056: f64 = v148 * v68;
        let v3057: f64 = v2112 - v3056;
        let v3058: f64 = v109 * v3036;
        let v3059: f64 = v129 * v3038;
        let v3060: f64 = v3058 - v3059;
        let v3061: f64 = v159 * v68;
        let v3062: f64 = v3060 - v3061;
        let v3063: f64 = v3057 + v3062;
        let v3064: f64 = v68 * v3063;
        let v3065: f64 = v3055 + v3064;
        let v3066: f64 = v3054 - v3065;
        let v3067: f64 = v151 * v68;
        let v3068: f64 = v91 * v65;
        let v3069: f64 = v3067 + v3068;
        let v3070: f64 = v136 * v68;
        let v3071: f64 = v114 * v3036;
        let v3072: f64 = v3070 + v3071;
        let v3073: f64 = v96 * v3072;
        let v3074: f64 = v114 * v3038;
        let v3075: f64 = v112 * v68;
        let v3076: f64 = v3074 - v3075;
        let v3077: f64 = v99 * v3076;
        let v3078: f64 = v3073 + v3077;
        let v3079: f64 = v3069 + v3078;
        let v3080: f64 = v10 * v3079;
        let v3081: f64 = v3066 + v3080;
        let v3082: f64 = v40 * v3081;
        let v3083: f64 = v96 * v3076;
        let v3084: f64 = v99 * v3072;
        let v3085: f64 = v3083 - v3084;
        let v3086: f64 = v3085 - v2174;
        let v3087: f64 = v65 * v3086;
        let v3088: f64 = v2172 * v68;
        let v3089: f64 = v3087 - v3088;
        let v3090: f64 = v2178 * v65;
        let v3091: f64 = v112 * v3036;
        let v3092: f64 = v136 * v3038;
        let v3093: f64 = v3091 + v3092;
        let v3094: f64 = v2168 + v3093;
        let v3095: f64 = v68 * v3094;
        let v3096: f64 = v3090 + v3095;
        let v3097: f64 = v3089 + v3096;
        let v3098: f64 = v10 * v3097;
        let v3099: f64 = v72 * v65;
        let v3100: f64 = v145 * v68;
        let v3101: f64 = v3099 - v3100;
        let v3102: f64 = v99 * v3042;
        let v3103: f64 = v96 * v3048;
        let v3104: f64 = v3102 + v3103;
        let v3105: f64 = v3101 + v3104;
        let v3106: f64 = v3098 - v3105;
        let v3107: f64 = v48 * v3106;
        let v3108: f64 = v3082 + v3107;
        let v3109: f64 = v65 * v3094;
        let v3110: f64 = v2178 * v68;
        let v3111: f64 = v3109 - v3110;
        let v3112: f64 = v2172 * v65;
        let v3113: f64 = v68 * v3086;
        let v3114: f64 = v3112 + v3113;
        let v3115: f64 = v3111 - v3114;
        let v3116: f64 = v29 * v3115;
        let v3117: f64 = v3108 + v3116;
        let v3118: f64 = v15 * v3117;
        let v3119: f64 = v2129 * v65;
        (
            v2935,
            v2943,
            v2954,
            v2958,
            v2964,
            v2971,
            v2984,
            v2993,
            v2997,
            v2998,
            v3017,
            v3029,
            v3033,
            v3051,
            v3061,
            v3062,
            v3063,
            v3079,
            v3081,
            v3097,
            v3105,
            v3106,
            v3115,
            v3117,
            v3118,
            v3119,
        )
    };
    let (
        v3125,
        v3132,
        v3145,
        v3152,
        v3168,
        v3177,
        v3204,
        v3226,
        v3227,
        v3232,
        v3242,
        v3247,
        v3258,
        v3265,
        v3281,
        v3285,
        v3286,
        v3298,
        v3301,
        v3305,
        v3306,
        v3311,
        v3313,
        v3314,
    ) = {
        let v3120: f64 = v68 * v3051;
        let v3121: f64 = v3119 + v3120;
        let v3122: f64 = v65 * v3063;
        let v3123: f64 = v2139 * v68;
        let v3124: f64 = v3122 - v3123;
        let v3125: f64 = v3121 + v3124;
        let v3126: f64 = v48 * v3097;
        let v3127: f64 = v40 * v3079;
        let v3128: f64 = v3126 + v3127;
        let v3129: f64 = v33 * v3128;
        let v3130: f64 = v48 * v3079;
        let v3131: f64 = v40 * v3097;
        let v3132: f64 = v3130 - v3131;
        let v3133: f64 = v29 * v3132;
        let v3134: f64 = v3129 + v3133;
        let v3135: f64 = v3125 - v3134;
        let v3136: f64 = v18 * v3135;
        let v3137: f64 = v3118 - v3136;
        let v3138: f64 = v3 * v3137;
        let v3139: f64 = v18 * v3117;
        let v3140: f64 = v15 * v3135;
        let v3141: f64 = v3139 + v3140;
        let v3142: f64 = v10 * v3128;
        let v3143: f64 = v3141 - v3142;
        let v3144: f64 = v6 * v3143;
        let v3145: f64 = v3138 + v3144;
        let v3146: f64 = v2417 * v40;
        let v3147: f64 = v2399 * v48;
        let v3148: f64 = v3146 - v3147;
        let v3149: f64 = v15 * v3148;
        let v3150: f64 = v2397 * v40;
        let v3151: f64 = v2415 * v48;
        let v3152: f64 = v3150 - v3151;
        let v3153: f64 = v29 * v3152;
        let v3154: f64 = v2397 * v48;
        let v3155: f64 = v2415 * v40;
        let v3156: f64 = v3154 + v3155;
        let v3157: f64 = v33 * v3156;
        let v3158: f64 = v3153 - v3157;
        let v3159: f64 = v18 * v3158;
        let v3160: f64 = v3149 - v3159;
        let v3161: f64 = v3 * v3160;
        let v3162: f64 = v18 * v3148;
        let v3163: f64 = v15 * v3158;
        let v3164: f64 = v3162 + v3163;
        let v3165: f64 = v10 * v3156;
        let v3166: f64 = v3164 - v3165;
        let v3167: f64 = v6 * v3166;
        let v3168: f64 = v3161 + v3167;
        let v3169: f64 = v3145 + v3168;
        let v3170: f64 = v0 * v3169;
        let v3171: f64 = v3170 * v1280;
        let v3172: f64 = v3033 + v3171;
        let v3173: f64 = v68 * v99;
        let v3174: f64 = v109 * v3173;
        let v3175: f64 = v68 * v96;
        let v3176: f64 = v129 * v3175;
        let v3177: f64 = v3174 + v3176;
        let v3178: f64 = v68 * v3177;
        let v3179: f64 = v2120 * v99;
        let v3180: f64 = v97 * v3173;
        let v3181: f64 = v103 * v3175;
        let v3182: f64 = v3180 + v3181;
        let v3183: f64 = v96 * v3182;
        let v3184: f64 = v3179 + v3183;
        let v3185: f64 = v2126 * v96;
        let v3186: f64 = v103 * v3173;
        let v3187: f64 = v126 * v3175;
        let v3188: f64 = v3186 + v3187;
        let v3189: f64 = v99 * v3188;
        let v3190: f64 = v3185 - v3189;
        let v3191: f64 = v3184 + v3190;
        let v3192: f64 = v65 * v3191;
        let v3193: f64 = v3178 - v3192;
        let v3194: f64 = v114 * v3173;
        let v3195: f64 = v96 * v3194;
        let v3196: f64 = v2148 * v99;
        let v3197: f64 = v3195 - v3196;
        let v3198: f64 = v2152 * v96;
        let v3199: f64 = v114 * v3175;
        let v3200: f64 = v99 * v3199;
        let v3201: f64 = v3198 + v3200;
        let v3202: f64 = v3197 - v3201;
        let v3203: f64 = v10 * v3202;
        let v3204: f64 = v3193 - v3203;
        let v3205: f64 = v40 * v3204;
        let v3206: f64 = v96 * v3199;
        let v3207: f64 = v2152 * v99;
        let v3208: f64 = v3206 - v3207;
        let v3209: f64 = v2148 * v96;
        let v3210: f64 = v99 * v3194;
        let v3211: f64 = v3209 + v3210;
        let v3212: f64 = v3208 + v3211;
        let v3213: f64 = v65 * v3212;
        let v3214: f64 = v136 * v3175;
        let v3215: f64 = v112 * v3173;
        let v3216: f64 = v3214 - v3215;
        let v3217: f64 = v68 * v3216;
        let v3218: f64 = v3213 + v3217;
        let v3219: f64 = v10 * v3218;
        let v3220: f64 = v2120 * v96;
        let v3221: f64 = v99 * v3182;
        let v3222: f64 = v3220 - v3221;
        let v3223: f64 = v2126 * v99;
        let v3224: f64 = v96 * v3188;
        let v3225: f64 = v3223 + v3224;
        let v3226: f64 = v3222 - v3225;
        let v3227: f64 = v3219 - v3226;
        let v3228: f64 = v48 * v3227;
        let v3229: f64 = v3205 + v3228;
        let v3230: f64 = v65 * v3216;
        let v3231: f64 = v68 * v3212;
        let v3232: f64 = v3230 - v3231;
        let v3233: f64 = v29 * v3232;
        let v3234: f64 = v3229 + v3233;
        let v3235: f64 = v15 * v3234;
        let v3236: f64 = v40 * v3202;
        let v3237: f64 = v48 * v3218;
        let v3238: f64 = v3236 - v3237;
        let v3239: f64 = v33 * v3238;
        let v3240: f64 = v40 * v3218;
        let v3241: f64 = v48 * v3202;
        let v3242: f64 = v3240 + v3241;
        let v3243: f64 = v29 * v3242;
        let v3244: f64 = v3239 + v3243;
        let v3245: f64 = v68 * v3191;
        let v3246: f64 = v65 * v3177;
        let v3247: f64 = v3245 + v3246;
        let v3248: f64 = v3244 - v3247;
        let v3249: f64 = v18 * v3248;
        let v3250: f64 = v3235 - v3249;
        let v3251: f64 = v3 * v3250;
        let v3252: f64 = v18 * v3234;
        let v3253: f64 = v15 * v3248;
        let v3254: f64 = v3252 + v3253;
        let v3255: f64 = v10 * v3238;
        let v3256: f64 = v3254 + v3255;
        let v3257: f64 = v6 * v3256;
        let v3258: f64 = v3251 + v3257;
        let v3259: f64 = v2581 * v40;
        let v3260: f64 = v2571 * v48;
        let v3261: f64 = v3259 - v3260;
        let v3262: f64 = v15 * v3261;
        let v3263: f64 = v2569 * v40;
        let v3264: f64 = v2576 * v48;
        let v3265: f64 = v3263 - v3264;
        let v3266: f64 = v29 * v3265;
        let v3267: f64 = v2569 * v48;
        let v3268: f64 = v2576 * v40;
        let v3269: f64 = v3267 + v3268;
        let v3270: f64 = v33 * v3269;
        let v3271: f64 = v3266 - v3270;
        let v3272: f64 = v18 * v3271;
        let v3273: f64 = v3262 - v3272;
        let v3274: f64 = v3 * v3273;
        let v3275: f64 = v18 * v3261;
        let v3276: f64 = v15 * v3271;
        let v3277: f64 = v3275 + v3276;
        let v3278: f64 = v10 * v3269;
        let v3279: f64 = v3277 - v3278;
        let v3280: f64 = v6 * v3279;
        let v3281: f64 = v3274 + v3280;
        let v3282: f64 = v3258 + v3281;
        let v3283: f64 = v0 * v3282;
        let v3284: f64 = v3283 * v1392;
        let v3285: f64 = v3172 + v3284;
        let v3286: f64 = v1279 * v1395;
        let v3287: f64 = v2448 + v2375;
        let v3288: f64 = v0 * v3287;
        let v3289: f64 = v3288 * v618;
        let v3290: f64 = v3286 + v3289;
        let v3291: f64 = v2894 + v2885;
        let v3292: f64 = v0 * v3291;
        let v3293: f64 = v3292 * v896;
        let v3294: f64 = v3290 + v3293;
        let v3295: f64 = v3168 + v3145;
        let v3296: f64 = v0 * v3295;
        let v3297: f64 = v3296 * v1116;
        let v3298: f64 = v3294 + v3297;
        let v3299: f64 = v2390 * v65;
        let v3300: f64 = v2385 * v68;
        let v3301: f64 = v3299 - v3300;
        let v3302: f64 = v40 * v3301;
        let v3303: f64 = v2413 * v65;
        let v3304: f64 = v2408 * v68;
        let v3305: f64 = v3303 - v3304;
        let v3306: f64 = v10 * v3305;
        let v3307: f64 = v48 * v3306;
        let v3308: f64 = v3302 + v3307;
        let v3309: f64 = v2413 * v68;
        let v3310: f64 = v2408 * v65;
        let v3311: f64 = v3309 + v3310;
        let v3312: f64 = v29 * v3311;
        let v3313: f64 = v3308 - v3312;
        let v3314: f64 = v15 * v3313;
        (
            v3125,
            v3132,
            v3145,
            v3152,
            v3168,
            v3177,
            v3204,
            v3226,
            v3227,
            v3232,
            v3242,
            v3247,
            v3258,
            v3265,
            v3281,
            v3285,
            v3286,
            v3298,
            v3301,
            v3305,
            v3306,
            v3311,
            v3313,
            v3314,
        )
    };
    let (
        v3317,
        v3318,
        v3333,
        v3352,
        v3361,
        v3369,
        v3382,
        v3387,
        v3393,
        v3400,
        v3413,
        v3415,
        v3419,
        v3425,
        v3427,
        v3430,
        v3442,
        v3446,
        v3447,
        v3466,
        v3470,
        v3473,
        v3479,
        v3486,
        v3497,
        v3501,
        v3509,
    ) = {
        let v3315: f64 = v2385 * v65;
        let v3316: f64 = v2390 * v68;
        let v3317: f64 = v3315 + v3316;
        let v3318: f64 = v40 * v3305;
        let v3319: f64 = v29 * v3318;
        let v3320: f64 = v48 * v3305;
        let v3321: f64 = v33 * v3320;
        let v3322: f64 = v3319 - v3321;
        let v3323: f64 = v3317 + v3322;
        let v3324: f64 = v18 * v3323;
        let v3325: f64 = v3314 - v3324;
        let v3326: f64 = v3 * v3325;
        let v3327: f64 = v18 * v3313;
        let v3328: f64 = v15 * v3323;
        let v3329: f64 = v3327 + v3328;
        let v3330: f64 = v10 * v3320;
        let v3331: f64 = v3329 - v3330;
        let v3332: f64 = v6 * v3331;
        let v3333: f64 = v3326 + v3332;
        let v3334: f64 = v3333 + v3333;
        let v3335: f64 = v0 * v3334;
        let v3336: f64 = v3335 * v1280;
        let v3337: f64 = v3298 + v3336;
        let v3338: f64 = v2378 * v96;
        let v3339: f64 = v126 * v99;
        let v3340: f64 = v2381 - v3339;
        let v3341: f64 = v99 * v3340;
        let v3342: f64 = v3338 + v3341;
        let v3343: f64 = v97 * v96;
        let v3344: f64 = v3343 - v2376;
        let v3345: f64 = v96 * v3344;
        let v3346: f64 = v2382 * v99;
        let v3347: f64 = v3345 - v3346;
        let v3348: f64 = v3342 - v3347;
        let v3349: f64 = v65 * v3348;
        let v3350: f64 = v109 * v96;
        let v3351: f64 = v129 * v99;
        let v3352: f64 = v3350 - v3351;
        let v3353: f64 = v68 * v3352;
        let v3354: f64 = v3349 + v3353;
        let v3355: f64 = v2393 * v99;
        let v3356: f64 = v2405 - v3355;
        let v3357: f64 = v2395 * v96;
        let v3358: f64 = v3357 - v2406;
        let v3359: f64 = v3356 - v3358;
        let v3360: f64 = v10 * v3359;
        let v3361: f64 = v3354 - v3360;
        let v3362: f64 = v40 * v3361;
        let v3363: f64 = v2382 * v96;
        let v3364: f64 = v99 * v3344;
        let v3365: f64 = v3363 + v3364;
        let v3366: f64 = v96 * v3340;
        let v3367: f64 = v2378 * v99;
        let v3368: f64 = v3366 - v3367;
        let v3369: f64 = v3365 + v3368;
        let v3370: f64 = v2393 * v96;
        let v3371: f64 = v3370 + v2396;
        let v3372: f64 = v2395 * v99;
        let v3373: f64 = v3372 + v2394;
        let v3374: f64 = v3371 - v3373;
        let v3375: f64 = v65 * v3374;
        let v3376: f64 = v136 * v99;
        let v3377: f64 = v112 * v96;
        let v3378: f64 = v3376 + v3377;
        let v3379: f64 = v68 * v3378;
        let v3380: f64 = v3375 - v3379;
        let v3381: f64 = v10 * v3380;
        let v3382: f64 = v3369 + v3381;
        let v3383: f64 = v48 * v3382;
        let v3384: f64 = v3362 + v3383;
        let v3385: f64 = v65 * v3378;
        let v3386: f64 = v68 * v3374;
        let v3387: f64 = v3385 + v3386;
        let v3388: f64 = v29 * v3387;
        let v3389: f64 = v3384 - v3388;
        let v3390: f64 = v15 * v3389;
        let v3391: f64 = v68 * v3348;
        let v3392: f64 = v65 * v3352;
        let v3393: f64 = v3391 - v3392;
        let v3394: f64 = v40 * v3359;
        let v3395: f64 = v48 * v3380;
        let v3396: f64 = v3394 - v3395;
        let v3397: f64 = v33 * v3396;
        let v3398: f64 = v40 * v3380;
        let v3399: f64 = v48 * v3359;
        let v3400: f64 = v3398 + v3399;
        let v3401: f64 = v29 * v3400;
        let v3402: f64 = v3397 + v3401;
        let v3403: f64 = v3393 + v3402;
        let v3404: f64 = v18 * v3403;
        let v3405: f64 = v3390 - v3404;
        let v3406: f64 = v3 * v3405;
        let v3407: f64 = v18 * v3389;
        let v3408: f64 = v15 * v3403;
        let v3409: f64 = v3407 + v3408;
        let v3410: f64 = v10 * v3396;
        let v3411: f64 = v3409 + v3410;
        let v3412: f64 = v6 * v3411;
        let v3413: f64 = v3406 + v3412;
        let v3414: f64 = v2563 * v65;
        let v3415: f64 = v3414 - v3061;
        let v3416: f64 = v2575 * v68;
        let v3417: f64 = v48 * v3416;
        let v3418: f64 = v33 * v3417;
        let v3419: f64 = v40 * v3416;
        let v3420: f64 = v29 * v3419;
        let v3421: f64 = v3418 - v3420;
        let v3422: f64 = v3415 + v3421;
        let v3423: f64 = v15 * v3422;
        let v3424: f64 = v2563 * v68;
        let v3425: f64 = v3424 + v2137;
        let v3426: f64 = v40 * v3425;
        let v3427: f64 = v10 * v3416;
        let v3428: f64 = v48 * v3427;
        let v3429: f64 = v3426 + v3428;
        let v3430: f64 = v2575 * v65;
        let v3431: f64 = v29 * v3430;
        let v3432: f64 = v3429 + v3431;
        let v3433: f64 = v18 * v3432;
        let v3434: f64 = v3423 - v3433;
        let v3435: f64 = v10 * v3417;
        let v3436: f64 = v3434 + v3435;
        let v3437: f64 = v6 * v3436;
        let v3438: f64 = v15 * v3432;
        let v3439: f64 = v18 * v3422;
        let v3440: f64 = v3438 + v3439;
        let v3441: f64 = v3 * v3440;
        let v3442: f64 = v3437 - v3441;
        let v3443: f64 = v3413 + v3442;
        let v3444: f64 = v0 * v3443;
        let v3445: f64 = v3444 * v1392;
        let v3446: f64 = v3337 + v3445;
        let v3447: f64 = v1391 * v1395;
        let v3448: f64 = v2610 + v2560;
        let v3449: f64 = v0 * v3448;
        let v3450: f64 = v3449 * v618;
        let v3451: f64 = v3447 + v3450;
        let v3452: f64 = v2993 + v2984;
        let v3453: f64 = v0 * v3452;
        let v3454: f64 = v3453 * v896;
        let v3455: f64 = v3451 + v3454;
        let v3456: f64 = v3281 + v3258;
        let v3457: f64 = v0 * v3456;
        let v3458: f64 = v3457 * v1116;
        let v3459: f64 = v3455 + v3458;
        let v3460: f64 = v3442 + v3413;
        let v3461: f64 = v0 * v3460;
        let v3462: f64 = v3461 * v1280;
        let v3463: f64 = v3459 + v3462;
        let v3464: f64 = v10 * v3378;
        let v3465: f64 = v65 * v2389;
        let v3466: f64 = v3464 - v3465;
        let v3467: f64 = v40 * v3466;
        let v3468: f64 = v65 * v2412;
        let v3469: f64 = v10 * v3468;
        let v3470: f64 = v3469 - v3352;
        let v3471: f64 = v48 * v3470;
        let v3472: f64 = v3467 + v3471;
        let v3473: f64 = v68 * v2412;
        let v3474: f64 = v29 * v3473;
        let v3475: f64 = v3472 - v3474;
        let v3476: f64 = v15 * v3475;
        let v3477: f64 = v40 * v3468;
        let v3478: f64 = v48 * v3378;
        let v3479: f64 = v3477 - v3478;
        let v3480: f64 = v29 * v3479;
        let v3481: f64 = v40 * v3378;
        let v3482: f64 = v48 * v3468;
        let v3483: f64 = v3481 + v3482;
        let v3484: f64 = v33 * v3483;
        let v3485: f64 = v3480 - v3484;
        let v3486: f64 = v68 * v2389;
        let v3487: f64 = v3485 - v3486;
        let v3488: f64 = v18 * v3487;
        let v3489: f64 = v3476 - v3488;
        let v3490: f64 = v3 * v3489;
        let v3491: f64 = v18 * v3475;
        let v3492: f64 = v15 * v3487;
        let v3493: f64 = v3491 + v3492;
        let v3494: f64 = v10 * v3483;
        let v3495: f64 = v3493 - v3494;
        let v3496: f64 = v6 * v3495;
        let v3497: f64 = v3490 + v3496;
        let v3498: f64 = v3497 + v3497;
        let v3499: f64 = v0 * v3498;
        let v3500: f64 = v3499 * v1392;
        let v3501: f64 = v3463 + v3500;
        let v3502: f64 = v319 * v15;
        let v3503: f64 = v18 * v876;
        let v3504: f64 = v3502 + v3503;
        let v3505: f64 = v15 * v832;
        let v3506: f64 = v275 * v18;
        let v3507: f64 = v3505 - v3506;
        let v3508: f64 = v3504 + v3507;
        let v3509: f64 = v10 * v3508;
        (
            v3317,
            v3318,
            v3333,
            v3352,
            v3361,
            v3369,
            v3382,
            v3387,
            v3393,
            v3400,
            v3413,
            v3415,
            v3419,
            v3425,
            v3427,
            v3430,
            v3442,
            v3446,
            v3447,
            v3466,
            v3470,
            v3473,
            v3479,
            v3486,
            v3497,
            v3501,
            v3509,
        )
    };
    let (
        v3522,
        v3523,
        v3536,
        v3553,
        v3554,
        v3567,
        v3568,
        v3581,
        v3582,
        v3586,
        v3617,
        v3634,
        v3636,
        v3647,
        v3649,
        v3660,
        v3662,
        v3664,
        v3668,
        v3673,
        v3690,
        v3691,
        v3695,
        v3699,
        v3703,
        v3704,
    ) = {
        let v3510: f64 = v1404 * v622;
        let v3511: f64 = v1599 * v626;
        let v3512: f64 = v3510 - v3511;
        let v3513: f64 = v283 * v629;
        let v3514: f64 = v32 * v643;
        let v3515: f64 = v3513 - v3514;
        let v3516: f64 = v3512 - v3515;
        let v3517: f64 = v48 * v761;
        let v3518: f64 = v40 * v816;
        let v3519: f64 = v3517 - v3518;
        let v3520: f64 = v3516 + v3519;
        let v3521: f64 = v33 * v832;
        let v3522: f64 = v3520 - v3521;
        let v3523: f64 = v3509 - v3522;
        let v3524: f64 = v1404 * v25;
        let v3525: f64 = v1599 * v20;
        let v3526: f64 = v3524 - v3525;
        let v3527: f64 = v283 * v54;
        let v3528: f64 = v32 * v30;
        let v3529: f64 = v3527 - v3528;
        let v3530: f64 = v3526 - v3529;
        let v3531: f64 = v48 * v465;
        let v3532: f64 = v40 * v520;
        let v3533: f64 = v3531 - v3532;
        let v3534: f64 = v3530 + v3533;
        let v3535: f64 = v33 * v533;
        let v3536: f64 = v3534 - v3535;
        let v3537: f64 = v3523 + v3536;
        let v3538: f64 = v0 * v3537;
        let v3539: f64 = v3538 * v896;
        let v3540: f64 = v3539 - v1396;
        let v3541: f64 = v18 * v1101;
        let v3542: f64 = v15 * v1072;
        let v3543: f64 = v3541 + v3542;
        let v3544: f64 = v10 * v3543;
        let v3545: f64 = v200 * v40;
        let v3546: f64 = v48 * v1010;
        let v3547: f64 = v3545 + v3546;
        let v3548: f64 = v40 * v1062;
        let v3549: f64 = v258 * v48;
        let v3550: f64 = v3548 - v3549;
        let v3551: f64 = v3547 - v3550;
        let v3552: f64 = v33 * v1072;
        let v3553: f64 = v3551 - v3552;
        let v3554: f64 = v3544 - v3553;
        let v3555: f64 = v3554 - v554;
        let v3556: f64 = v0 * v3555;
        let v3557: f64 = v3556 * v1116;
        let v3558: f64 = v3540 + v3557;
        let v3559: f64 = v18 * v1265;
        let v3560: f64 = v15 * v1248;
        let v3561: f64 = v3559 + v3560;
        let v3562: f64 = v10 * v3561;
        let v3563: f64 = v48 * v1202;
        let v3564: f64 = v40 * v1239;
        let v3565: f64 = v3563 + v3564;
        let v3566: f64 = v33 * v1248;
        let v3567: f64 = v3565 - v3566;
        let v3568: f64 = v3562 - v3567;
        let v3569: f64 = v3568 + v488;
        let v3570: f64 = v0 * v3569;
        let v3571: f64 = v3570 * v1280;
        let v3572: f64 = v3558 + v3571;
        let v3573: f64 = v15 * v1364;
        let v3574: f64 = v18 * v1377;
        let v3575: f64 = v3573 - v3574;
        let v3576: f64 = v10 * v3575;
        let v3577: f64 = v48 * v1336;
        let v3578: f64 = v40 * v1359;
        let v3579: f64 = v3577 - v3578;
        let v3580: f64 = v33 * v1364;
        let v3581: f64 = v3579 - v3580;
        let v3582: f64 = v3576 - v3581;
        let v3583: f64 = v3582 - v434;
        let v3584: f64 = v0 * v3583;
        let v3585: f64 = v3584 * v1392;
        let v3586: f64 = v3572 + v3585;
        let v3587: f64 = v1397 * v6;
        let v3588: f64 = v1620 * v3;
        let v3589: f64 = v3587 - v3588;
        let v3590: f64 = v3589 - v3536;
        let v3591: f64 = v18 * v569;
        let v3592: f64 = v15 * v533;
        let v3593: f64 = v3591 + v3592;
        let v3594: f64 = v1398 * v6;
        let v3595: f64 = v3593 - v3594;
        let v3596: f64 = v10 * v3595;
        let v3597: f64 = v3590 + v3596;
        let v3598: f64 = v3597 - v1628;
        let v3599: f64 = v0 * v3598;
        let v3600: f64 = v3599 * v1395;
        let v3601: f64 = v1612 * v15;
        let v3602: f64 = v18 * v1744;
        let v3603: f64 = v3601 + v3602;
        let v3604: f64 = v15 * v1720;
        let v3605: f64 = v1584 * v18;
        let v3606: f64 = v3604 - v3605;
        let v3607: f64 = v3603 + v3606;
        let v3608: f64 = v10 * v3607;
        let v3609: f64 = v32 * v1401;
        let v3610: f64 = v283 * v1409;
        let v3611: f64 = v3609 + v3610;
        let v3612: f64 = v48 * v1684;
        let v3613: f64 = v40 * v1711;
        let v3614: f64 = v3612 + v3613;
        let v3615: f64 = v3611 + v3614;
        let v3616: f64 = v33 * v1720;
        let v3617: f64 = v3615 - v3616;
        let v3618: f64 = v3608 - v3617;
        let v3619: f64 = v0 * v3618;
        let v3620: f64 = v3619 * v896;
        let v3621: f64 = v3600 + v3620;
        let v3622: f64 = v18 * v2097;
        let v3623: f64 = v15 * v2068;
        let v3624: f64 = v3622 + v3623;
        let v3625: f64 = v10 * v3624;
        let v3626: f64 = v1518 * v40;
        let v3627: f64 = v48 * v2008;
        let v3628: f64 = v3626 + v3627;
        let v3629: f64 = v1569 * v48;
        let v3630: f64 = v40 * v2058;
        let v3631: f64 = v3629 + v3630;
        let v3632: f64 = v3628 + v3631;
        let v3633: f64 = v33 * v2068;
        let v3634: f64 = v3632 - v3633;
        let v3635: f64 = v3625 - v3634;
        let v3636: f64 = v0 * v3635;
        let v3637: f64 = v3636 * v1116;
        let v3638: f64 = v3621 + v3637;
        let v3639: f64 = v18 * v2362;
        let v3640: f64 = v15 * v2345;
        let v3641: f64 = v3639 + v3640;
        let v3642: f64 = v10 * v3641;
        let v3643: f64 = v48 * v2299;
        let v3644: f64 = v40 * v2336;
        let v3645: f64 = v3643 + v3644;
        let v3646: f64 = v33 * v2345;
        let v3647: f64 = v3645 - v3646;
        let v3648: f64 = v3642 - v3647;
        let v3649: f64 = v0 * v3648;
        let v3650: f64 = v3649 * v1280;
        let v3651: f64 = v3638 + v3650;
        let v3652: f64 = v18 * v2547;
        let v3653: f64 = v15 * v2534;
        let v3654: f64 = v3652 + v3653;
        let v3655: f64 = v10 * v3654;
        let v3656: f64 = v48 * v2506;
        let v3657: f64 = v40 * v2529;
        let v3658: f64 = v3656 + v3657;
        let v3659: f64 = v33 * v2534;
        let v3660: f64 = v3658 - v3659;
        let v3661: f64 = v3655 - v3660;
        let v3662: f64 = v0 * v3661;
        let v3663: f64 = v3662 * v1392;
        let v3664: f64 = v3651 + v3663;
        let v3665: f64 = v3523 - v1902;
        let v3666: f64 = v0 * v3665;
        let v3667: f64 = v3666 * v1395;
        let v3668: f64 = v3619 * v618;
        let v3669: f64 = v3667 + v3668;
        let v3670: f64 = v1889 * v15;
        let v3671: f64 = v1869 * v18;
        let v3672: f64 = v3670 - v3671;
        let v3673: f64 = v10 * v3672;
        let v3674: f64 = v3673 + v3673;
        let v3675: f64 = v0 * v3674;
        let v3676: f64 = v3675 * v896;
        let v3677: f64 = v3669 + v3676;
        let v3678: f64 = v18 * v2747;
        let v3679: f64 = v15 * v2721;
        let v3680: f64 = v3678 + v3679;
        let v3681: f64 = v10 * v3680;
        let v3682: f64 = v1824 * v40;
        let v3683: f64 = v48 * v2683;
        let v3684: f64 = v3682 + v3683;
        let v3685: f64 = v1857 * v48;
        let v3686: f64 = v40 * v2714;
        let v3687: f64 = v3685 + v3686;
        let v3688: f64 = v3684 + v3687;
        let v3689: f64 = v33 * v2721;
        let v3690: f64 = v3688 - v3689;
        let v3691: f64 = v3681 - v3690;
        let v3692: f64 = v2202 * v15;
        let v3693: f64 = v2188 * v18;
        let v3694: f64 = v3692 - v3693;
        let v3695: f64 = v10 * v3694;
        let v3696: f64 = v3691 + v3695;
        let v3697: f64 = v0 * v3696;
        let v3698: f64 = v3697 * v1116;
        let v3699: f64 = v3677 + v3698;
        let v3700: f64 = v18 * v2872;
        let v3701: f64 = v15 * v2855;
        let v3702: f64 = v3700 + v3701;
        let v3703: f64 = v10 * v3702;
        let v3704: f64 = v48 * v2817;
        (
            v3522,
            v3523,
            v3536,
            v3553,
            v3554,
            v3567,
            v3568,
            v3581,
            v3582,
            v3586,
            v3617,
            v3634,
            v3636,
            v3647,
            v3649,
            v3660,
            v3662,
            v3664,
            v3668,
            v3673,
            v3690,
            v3691,
            v3695,
            v3699,
            v3703,
            v3704,
        )
    };
    let (
        v3708,
        v3709,
        v3713,
        v3726,
        v3727,
        v3731,
        v3735,
        v3739,
        v3749,
        v3750,
        v3763,
        v3764,
        v3769,
        v3770,
        v3783,
        v3784,
        v3787,
        v3790,
        v3794,
        v3798,
        v3812,
        v3813,
        v3826,
        v3827,
        v3832,
        v3837,
        v3841,
        v3845,
        v3859,
        v3864,
        v3868,
        v3884,
        v3896,
        v3899,
    ) = {
        let v3705: f64 = v40 * v2846;
        let v3706: f64 = v3704 + v3705;
        let v3707: f64 = v33 * v2855;
        let v3708: f64 = v3706 - v3707;
        let v3709: f64 = v3703 - v3708;
        let v3710: f64 = v2422 * v18;
        let v3711: f64 = v2435 * v15;
        let v3712: f64 = v3710 + v3711;
        let v3713: f64 = v10 * v3712;
        let v3714: f64 = v3709 - v3713;
        let v3715: f64 = v0 * v3714;
        let v3716: f64 = v3715 * v1280;
        let v3717: f64 = v3699 + v3716;
        let v3718: f64 = v18 * v2971;
        let v3719: f64 = v15 * v2958;
        let v3720: f64 = v3718 + v3719;
        let v3721: f64 = v10 * v3720;
        let v3722: f64 = v48 * v2935;
        let v3723: f64 = v40 * v2954;
        let v3724: f64 = v3722 + v3723;
        let v3725: f64 = v33 * v2958;
        let v3726: f64 = v3724 - v3725;
        let v3727: f64 = v3721 - v3726;
        let v3728: f64 = v2597 * v15;
        let v3729: f64 = v2584 * v18;
        let v3730: f64 = v3728 - v3729;
        let v3731: f64 = v10 * v3730;
        let v3732: f64 = v3727 - v3731;
        let v3733: f64 = v0 * v3732;
        let v3734: f64 = v3733 * v1392;
        let v3735: f64 = v3717 + v3734;
        let v3736: f64 = v3554 - v2215;
        let v3737: f64 = v0 * v3736;
        let v3738: f64 = v3737 * v1395;
        let v3739: f64 = v3636 * v618;
        let v3740: f64 = v3738 + v3739;
        let v3741: f64 = v3695 + v3691;
        let v3742: f64 = v0 * v3741;
        let v3743: f64 = v3742 * v896;
        let v3744: f64 = v3740 + v3743;
        let v3745: f64 = v18 * v3017;
        let v3746: f64 = v10 * v3745;
        let v3747: f64 = v2158 * v40;
        let v3748: f64 = v2183 * v48;
        let v3749: f64 = v3747 + v3748;
        let v3750: f64 = v3746 + v3749;
        let v3751: f64 = v3750 + v3750;
        let v3752: f64 = v0 * v3751;
        let v3753: f64 = v3752 * v1116;
        let v3754: f64 = v3744 - v3753;
        let v3755: f64 = v18 * v3132;
        let v3756: f64 = v15 * v3115;
        let v3757: f64 = v3755 + v3756;
        let v3758: f64 = v10 * v3757;
        let v3759: f64 = v48 * v3081;
        let v3760: f64 = v40 * v3106;
        let v3761: f64 = v3759 - v3760;
        let v3762: f64 = v33 * v3115;
        let v3763: f64 = v3761 - v3762;
        let v3764: f64 = v3758 - v3763;
        let v3765: f64 = v18 * v3152;
        let v3766: f64 = v10 * v3765;
        let v3767: f64 = v2399 * v40;
        let v3768: f64 = v2417 * v48;
        let v3769: f64 = v3767 + v3768;
        let v3770: f64 = v3766 + v3769;
        let v3771: f64 = v3764 - v3770;
        let v3772: f64 = v0 * v3771;
        let v3773: f64 = v3772 * v1280;
        let v3774: f64 = v3754 + v3773;
        let v3775: f64 = v15 * v3232;
        let v3776: f64 = v18 * v3242;
        let v3777: f64 = v3775 - v3776;
        let v3778: f64 = v10 * v3777;
        let v3779: f64 = v48 * v3204;
        let v3780: f64 = v40 * v3227;
        let v3781: f64 = v3779 - v3780;
        let v3782: f64 = v33 * v3232;
        let v3783: f64 = v3781 - v3782;
        let v3784: f64 = v3778 - v3783;
        let v3785: f64 = v2571 * v40;
        let v3786: f64 = v2581 * v48;
        let v3787: f64 = v3785 + v3786;
        let v3788: f64 = v18 * v3265;
        let v3789: f64 = v10 * v3788;
        let v3790: f64 = v3787 + v3789;
        let v3791: f64 = v3784 - v3790;
        let v3792: f64 = v0 * v3791;
        let v3793: f64 = v3792 * v1392;
        let v3794: f64 = v3774 + v3793;
        let v3795: f64 = v3568 - v2448;
        let v3796: f64 = v0 * v3795;
        let v3797: f64 = v3796 * v1395;
        let v3798: f64 = v3649 * v618;
        let v3799: f64 = v3797 + v3798;
        let v3800: f64 = v3715 * v896;
        let v3801: f64 = v3799 + v3800;
        let v3802: f64 = v3772 * v1116;
        let v3803: f64 = v3801 + v3802;
        let v3804: f64 = v15 * v3311;
        let v3805: f64 = v18 * v3318;
        let v3806: f64 = v3804 + v3805;
        let v3807: f64 = v10 * v3806;
        let v3808: f64 = v48 * v3301;
        let v3809: f64 = v40 * v3306;
        let v3810: f64 = v3808 - v3809;
        let v3811: f64 = v33 * v3311;
        let v3812: f64 = v3810 + v3811;
        let v3813: f64 = v3807 + v3812;
        let v3814: f64 = v3813 + v3813;
        let v3815: f64 = v0 * v3814;
        let v3816: f64 = v3815 * v1280;
        let v3817: f64 = v3803 - v3816;
        let v3818: f64 = v15 * v3387;
        let v3819: f64 = v18 * v3400;
        let v3820: f64 = v3818 + v3819;
        let v3821: f64 = v10 * v3820;
        let v3822: f64 = v48 * v3361;
        let v3823: f64 = v40 * v3382;
        let v3824: f64 = v3822 - v3823;
        let v3825: f64 = v33 * v3387;
        let v3826: f64 = v3824 + v3825;
        let v3827: f64 = v3821 + v3826;
        let v3828: f64 = v40 * v3427;
        let v3829: f64 = v48 * v3425;
        let v3830: f64 = v3828 - v3829;
        let v3831: f64 = v33 * v3430;
        let v3832: f64 = v3830 + v3831;
        let v3833: f64 = v15 * v3430;
        let v3834: f64 = v18 * v3419;
        let v3835: f64 = v3833 - v3834;
        let v3836: f64 = v10 * v3835;
        let v3837: f64 = v3832 + v3836;
        let v3838: f64 = v3827 + v3837;
        let v3839: f64 = v0 * v3838;
        let v3840: f64 = v3839 * v1392;
        let v3841: f64 = v3817 - v3840;
        let v3842: f64 = v3582 - v2610;
        let v3843: f64 = v0 * v3842;
        let v3844: f64 = v3843 * v1395;
        let v3845: f64 = v3662 * v618;
        let v3846: f64 = v3844 + v3845;
        let v3847: f64 = v3733 * v896;
        let v3848: f64 = v3846 + v3847;
        let v3849: f64 = v3792 * v1116;
        let v3850: f64 = v3848 + v3849;
        let v3851: f64 = v3837 + v3827;
        let v3852: f64 = v0 * v3851;
        let v3853: f64 = v3852 * v1280;
        let v3854: f64 = v3850 - v3853;
        let v3855: f64 = v48 * v3466;
        let v3856: f64 = v40 * v3470;
        let v3857: f64 = v3855 - v3856;
        let v3858: f64 = v33 * v3473;
        let v3859: f64 = v3857 + v3858;
        let v3860: f64 = v18 * v3479;
        let v3861: f64 = v15 * v3473;
        let v3862: f64 = v3860 + v3861;
        let v3863: f64 = v10 * v3862;
        let v3864: f64 = v3859 + v3863;
        let v3865: f64 = v3864 + v3864;
        let v3866: f64 = v0 * v3865;
        let v3867: f64 = v3866 * v1392;
        let v3868: f64 = v3854 - v3867;
        let v3869: f64 = v784 - v3567;
        let v3870: f64 = v0 * v3869;
        let v3871: f64 = v3870 * v1280;
        let v3872: f64 = v3536 + v3523;
        let v3873: f64 = v0 * v3872;
        let v3874: f64 = v3873 * v618;
        let v3875: f64 = v2615 + v3874;
        let v3876: f64 = v3553 + v858;
        let v3877: f64 = v0 * v3876;
        let v3878: f64 = v3877 * v1116;
        let v3879: f64 = v3875 + v3878;
        let v3880: f64 = v3871 - v3879;
        let v3881: f64 = v3581 + v730;
        let v3882: f64 = v0 * v3881;
        let v3883: f64 = v3882 * v1392;
        let v3884: f64 = v3880 - v3883;
        let v3885: f64 = v1695 - v3647;
        let v3886: f64 = v0 * v3885;
        let v3887: f64 = v3886 * v1280;
        let v3888: f64 = v3536 + v1762;
        let v3889: f64 = v0 * v3888;
        let v3890: f64 = v3889 * v1395;
        let v3891: f64 = v3890 + v3668;
        let v3892: f64 = v3634 + v1733;
        let v3893: f64 = v0 * v3892;
        let v3894: f64 = v3893 * v1116;
        let v3895: f64 = v3891 + v3894;
        let v3896: f64 = v3887 - v3895;
        let v3897: f64 = v1669 - v3660;
        let v3898: f64 = v0 * v3897;
        let v3899: f64 = v3898 * v1392;
        (
            v3708,
            v3709,
            v3713,
            v3726,
            v3727,
            v3731,
            v3735,
            v3739,
            v3749,
            v3750,
            v3763,
            v3764,
            v3769,
            v3770,
            v3783,
            v3784,
            v3787,
            v3790,
            v3794,
            v3798,
            v3812,
            v3813,
            v3826,
            v3827,
            v3832,
            v3837,
            v3841,
            v3845,
            v3859,
            v3864,
            v3868,
            v3884,
            v3896,
            v3899,
        )
    };
    let (
        v3900,
        v3917,
        v3939,
        v3947,
        v3960,
        v3968,
        v3981,
        v3997,
        v4013,
        v4029,
        v4046,
        v4058,
        v4067,
        v4079,
        v4088,
        v4091,
        v4094,
    ) = {
        let v3900: f64 = v3896 + v3899;
        let v3901: f64 = v3522 + v2628;
        let v3902: f64 = v0 * v3901;
        let v3903: f64 = v3902 * v1395;
        let v3904: f64 = v3617 + v3673;
        let v3905: f64 = v0 * v3904;
        let v3906: f64 = v3905 * v618;
        let v3907: f64 = v3903 + v3906;
        let v3908: f64 = v0 * v3690;
        let v3909: f64 = v3908 * v1116;
        let v3910: f64 = v3907 + v3909;
        let v3911: f64 = v0 * v3708;
        let v3912: f64 = v3911 * v1280;
        let v3913: f64 = v3910 + v3912;
        let v3914: f64 = v0 * v3726;
        let v3915: f64 = v3914 * v1392;
        let v3916: f64 = v3913 + v3915;
        let v3917: f64 = -v3916;
        let v3918: f64 = v3553 + v2769;
        let v3919: f64 = v0 * v3918;
        let v3920: f64 = v3919 * v1395;
        let v3921: f64 = v3634 + v3695;
        let v3922: f64 = v0 * v3921;
        let v3923: f64 = v3922 * v618;
        let v3924: f64 = v3920 + v3923;
        let v3925: f64 = v3908 * v896;
        let v3926: f64 = v3924 + v3925;
        let v3927: f64 = v3749 + v3749;
        let v3928: f64 = v0 * v3927;
        let v3929: f64 = v3928 * v1116;
        let v3930: f64 = v3926 + v3929;
        let v3931: f64 = v3763 + v3769;
        let v3932: f64 = v0 * v3931;
        let v3933: f64 = v3932 * v1280;
        let v3934: f64 = v3930 + v3933;
        let v3935: f64 = v3783 + v3787;
        let v3936: f64 = v0 * v3935;
        let v3937: f64 = v3936 * v1392;
        let v3938: f64 = v3934 + v3937;
        let v3939: f64 = -v3938;
        let v3940: f64 = v3713 - v3647;
        let v3941: f64 = v0 * v3940;
        let v3942: f64 = v3941 * v618;
        let v3943: f64 = v3567 + v2894;
        let v3944: f64 = v0 * v3943;
        let v3945: f64 = v3944 * v1395;
        let v3946: f64 = v3942 - v3945;
        let v3947: f64 = v3911 * v896;
        let v3948: f64 = v3946 - v3947;
        let v3949: f64 = v3769 + v3763;
        let v3950: f64 = v0 * v3949;
        let v3951: f64 = v3950 * v1116;
        let v3952: f64 = v3948 - v3951;
        let v3953: f64 = v3812 + v3812;
        let v3954: f64 = v0 * v3953;
        let v3955: f64 = v3954 * v1280;
        let v3956: f64 = v3952 - v3955;
        let v3957: f64 = v3826 + v3832;
        let v3958: f64 = v0 * v3957;
        let v3959: f64 = v3958 * v1392;
        let v3960: f64 = v3956 - v3959;
        let v3961: f64 = v3731 - v3660;
        let v3962: f64 = v0 * v3961;
        let v3963: f64 = v3962 * v618;
        let v3964: f64 = v3581 + v2993;
        let v3965: f64 = v0 * v3964;
        let v3966: f64 = v3965 * v1395;
        let v3967: f64 = v3963 - v3966;
        let v3968: f64 = v3914 * v896;
        let v3969: f64 = v3967 - v3968;
        let v3970: f64 = v3787 + v3783;
        let v3971: f64 = v0 * v3970;
        let v3972: f64 = v3971 * v1116;
        let v3973: f64 = v3969 - v3972;
        let v3974: f64 = v3832 + v3826;
        let v3975: f64 = v0 * v3974;
        let v3976: f64 = v3975 * v1280;
        let v3977: f64 = v3973 - v3976;
        let v3978: f64 = v3859 + v3859;
        let v3979: f64 = v0 * v3978;
        let v3980: f64 = v3979 * v1392;
        let v3981: f64 = v3977 - v3980;
        let v3982: f64 = v554 - v3554;
        let v3983: f64 = v0 * v3982;
        let v3984: f64 = v3983 * v618;
        let v3985: f64 = v3984 - v2998;
        let v3986: f64 = v858 + v3553;
        let v3987: f64 = v0 * v3986;
        let v3988: f64 = v3987 * v896;
        let v3989: f64 = v3985 + v3988;
        let v3990: f64 = v1258 + v1032;
        let v3991: f64 = v0 * v3990;
        let v3992: f64 = v3991 * v1280;
        let v3993: f64 = v3989 + v3992;
        let v3994: f64 = v1370 - v981;
        let v3995: f64 = v0 * v3994;
        let v3996: f64 = v3995 * v1392;
        let v3997: f64 = v3993 + v3996;
        let v3998: f64 = v554 - v2110;
        let v3999: f64 = v0 * v3998;
        let v4000: f64 = v3999 * v1395;
        let v4001: f64 = v4000 - v3739;
        let v4002: f64 = v1733 + v3634;
        let v4003: f64 = v0 * v4002;
        let v4004: f64 = v4003 * v896;
        let v4005: f64 = v4001 + v4004;
        let v4006: f64 = v2355 + v2029;
        let v4007: f64 = v0 * v4006;
        let v4008: f64 = v4007 * v1280;
        let v4009: f64 = v4005 + v4008;
        let v4010: f64 = v2540 - v1980;
        let v4011: f64 = v0 * v4010;
        let v4012: f64 = v4011 * v1392;
        let v4013: f64 = v4009 + v4012;
        let v4014: f64 = v858 - v2760;
        let v4015: f64 = v0 * v4014;
        let v4016: f64 = v4015 * v1395;
        let v4017: f64 = v1733 - v3691;
        let v4018: f64 = v0 * v4017;
        let v4019: f64 = v4018 * v618;
        let v4020: f64 = v4016 + v4019;
        let v4021: f64 = v4020 + v3925;
        let v4022: f64 = v2865 + v2696;
        let v4023: f64 = v0 * v4022;
        let v4024: f64 = v4023 * v1280;
        let v4025: f64 = v4021 + v4024;
        let v4026: f64 = v2964 - v2665;
        let v4027: f64 = v0 * v4026;
        let v4028: f64 = v4027 * v1392;
        let v4029: f64 = v4025 + v4028;
        let v4030: f64 = v1086 - v3029;
        let v4031: f64 = v0 * v4030;
        let v4032: f64 = v4031 * v1395;
        let v4033: f64 = v2082 + v3750;
        let v4034: f64 = v0 * v4033;
        let v4035: f64 = v4034 * v618;
        let v4036: f64 = v4032 + v4035;
        let v4037: f64 = v2732 + v3749;
        let v4038: f64 = v0 * v4037;
        let v4039: f64 = v4038 * v896;
        let v4040: f64 = v4036 + v4039;
        let v4041: f64 = v0 * v3125;
        let v4042: f64 = v4041 * v1280;
        let v4043: f64 = v4040 + v4042;
        let v4044: f64 = v0 * v3247;
        let v4045: f64 = v4044 * v1392;
        let v4046: f64 = v4043 - v4045;
        let v4047: f64 = v1258 - v3168;
        let v4048: f64 = v0 * v4047;
        let v4049: f64 = v4048 * v1395;
        let v4050: f64 = v2355 + v3770;
        let v4051: f64 = v0 * v4050;
        let v4052: f64 = v4051 * v618;
        let v4053: f64 = v4049 + v4052;
        let v4054: f64 = v2865 + v3769;
        let v4055: f64 = v0 * v4054;
        let v4056: f64 = v4055 * v896;
        let v4057: f64 = v4053 + v4056;
        let v4058: f64 = v4041 * v1116;
        let v4059: f64 = v4057 + v4058;
        let v4060: f64 = v3317 + v3317;
        let v4061: f64 = v0 * v4060;
        let v4062: f64 = v4061 * v1280;
        let v4063: f64 = v4059 + v4062;
        let v4064: f64 = v3393 + v3415;
        let v4065: f64 = v0 * v4064;
        let v4066: f64 = v4065 * v1392;
        let v4067: f64 = v4063 + v4066;
        let v4068: f64 = v1370 - v3281;
        let v4069: f64 = v0 * v4068;
        let v4070: f64 = v4069 * v1395;
        let v4071: f64 = v2540 + v3790;
        let v4072: f64 = v0 * v4071;
        let v4073: f64 = v4072 * v618;
        let v4074: f64 = v4070 + v4073;
        let v4075: f64 = v2964 + v3787;
        let v4076: f64 = v0 * v4075;
        let v4077: f64 = v4076 * v896;
        let v4078: f64 = v4074 + v4077;
        let v4079: f64 = v4044 * v1116;
        let v4080: f64 = v4078 - v4079;
        let v4081: f64 = v3415 + v3393;
        let v4082: f64 = v0 * v4081;
        let v4083: f64 = v4082 * v1280;
        let v4084: f64 = v4080 + v4083;
        let v4085: f64 = v3486 + v3486;
        let v4086: f64 = v0 * v4085;
        let v4087: f64 = v4086 * v1392;
        let v4088: f64 = v4084 - v4087;
        let v4089: f64 = v3567 - v784;
        let v4090: f64 = v0 * v4089;
        let v4091: f64 = v4090 * v896;
        let v4092: f64 = v488 + v3568;
        let v4093: f64 = v0 * v4092;
        let v4094: f64 = v4093 * v618;
        (
            v3900,
            v3917,
            v3939,
            v3947,
            v3960,
            v3968,
            v3981,
            v3997,
            v4013,
            v4029,
            v4046,
            v4058,
            v4067,
            v4079,
            v4088,
            v4091,
            v4094,
        )
    };
    let (
        v4104,
        v4120,
        v4136,
        v4152,
        v4170,
        v4191,
        v4207,
        v4223,
        v4239,
        v4255,
        v4271,
        v4286,
    ) = {
        let v4095: f64 = v3286 + v4094;
        let v4096: f64 = v4091 - v4095;
        let v4097: f64 = v1032 + v1258;
        let v4098: f64 = v0 * v4097;
        let v4099: f64 = v4098 * v1116;
        let v4100: f64 = v4096 - v4099;
        let v4101: f64 = v1358 + v1179;
        let v4102: f64 = v0 * v4101;
        let v4103: f64 = v4102 * v1392;
        let v4104: f64 = v4100 - v4103;
        let v4105: f64 = v3647 - v1695;
        let v4106: f64 = v0 * v4105;
        let v4107: f64 = v4106 * v896;
        let v4108: f64 = v488 + v2375;
        let v4109: f64 = v0 * v4108;
        let v4110: f64 = v4109 * v1395;
        let v4111: f64 = v4110 + v3798;
        let v4112: f64 = v4107 - v4111;
        let v4113: f64 = v2029 + v2355;
        let v4114: f64 = v0 * v4113;
        let v4115: f64 = v4114 * v1116;
        let v4116: f64 = v4112 - v4115;
        let v4117: f64 = v2514 + v2276;
        let v4118: f64 = v0 * v4117;
        let v4119: f64 = v4118 * v1392;
        let v4120: f64 = v4116 - v4119;
        let v4121: f64 = v784 + v2885;
        let v4122: f64 = v0 * v4121;
        let v4123: f64 = v4122 * v1395;
        let v4124: f64 = v1695 + v3709;
        let v4125: f64 = v0 * v4124;
        let v4126: f64 = v4125 * v618;
        let v4127: f64 = v4123 + v4126;
        let v4128: f64 = v3947 - v4127;
        let v4129: f64 = v2696 + v2865;
        let v4130: f64 = v0 * v4129;
        let v4131: f64 = v4130 * v1116;
        let v4132: f64 = v4128 - v4131;
        let v4133: f64 = v2943 + v2803;
        let v4134: f64 = v0 * v4133;
        let v4135: f64 = v4134 * v1392;
        let v4136: f64 = v4132 - v4135;
        let v4137: f64 = v3763 - v2696;
        let v4138: f64 = v0 * v4137;
        let v4139: f64 = v4138 * v896;
        let v4140: f64 = v1032 + v3145;
        let v4141: f64 = v0 * v4140;
        let v4142: f64 = v4141 * v1395;
        let v4143: f64 = v2029 + v3764;
        let v4144: f64 = v0 * v4143;
        let v4145: f64 = v4144 * v618;
        let v4146: f64 = v4142 + v4145;
        let v4147: f64 = v4139 - v4146;
        let v4148: f64 = v4147 - v4058;
        let v4149: f64 = v3226 + v3062;
        let v4150: f64 = v0 * v4149;
        let v4151: f64 = v4150 * v1392;
        let v4152: f64 = v4148 - v4151;
        let v4153: f64 = v3813 - v2311;
        let v4154: f64 = v0 * v4153;
        let v4155: f64 = v4154 * v618;
        let v4156: f64 = v1214 + v3333;
        let v4157: f64 = v0 * v4156;
        let v4158: f64 = v4157 * v1395;
        let v4159: f64 = v4155 - v4158;
        let v4160: f64 = v3812 - v2826;
        let v4161: f64 = v0 * v4160;
        let v4162: f64 = v4161 * v896;
        let v4163: f64 = v4159 + v4162;
        let v4164: f64 = v3105 + v3317;
        let v4165: f64 = v0 * v4164;
        let v4166: f64 = v4165 * v1116;
        let v4167: f64 = v4163 - v4166;
        let v4168: f64 = v0 * v3369;
        let v4169: f64 = v4168 * v1392;
        let v4170: f64 = v4167 + v4169;
        let v4171: f64 = v3837 - v2514;
        let v4172: f64 = v0 * v4171;
        let v4173: f64 = v4172 * v618;
        let v4174: f64 = v1358 + v3442;
        let v4175: f64 = v0 * v4174;
        let v4176: f64 = v4175 * v1395;
        let v4177: f64 = v4173 - v4176;
        let v4178: f64 = v3832 - v2943;
        let v4179: f64 = v0 * v4178;
        let v4180: f64 = v4179 * v896;
        let v4181: f64 = v4177 + v4180;
        let v4182: f64 = v3226 + v3415;
        let v4183: f64 = v0 * v4182;
        let v4184: f64 = v4183 * v1116;
        let v4185: f64 = v4181 - v4184;
        let v4186: f64 = v4168 * v1280;
        let v4187: f64 = v4185 + v4186;
        let v4188: f64 = v3352 + v3352;
        let v4189: f64 = v0 * v4188;
        let v4190: f64 = v4189 * v1392;
        let v4191: f64 = v4187 - v4190;
        let v4192: f64 = v434 - v3582;
        let v4193: f64 = v0 * v4192;
        let v4194: f64 = v4193 * v618;
        let v4195: f64 = v4194 - v3447;
        let v4196: f64 = v730 + v3581;
        let v4197: f64 = v0 * v4196;
        let v4198: f64 = v4197 * v896;
        let v4199: f64 = v4195 + v4198;
        let v4200: f64 = v981 - v1370;
        let v4201: f64 = v0 * v4200;
        let v4202: f64 = v4201 * v1116;
        let v4203: f64 = v4199 + v4202;
        let v4204: f64 = v1179 + v1358;
        let v4205: f64 = v0 * v4204;
        let v4206: f64 = v4205 * v1280;
        let v4207: f64 = v4203 + v4206;
        let v4208: f64 = v434 - v2560;
        let v4209: f64 = v0 * v4208;
        let v4210: f64 = v4209 * v1395;
        let v4211: f64 = v4210 - v3845;
        let v4212: f64 = v3660 - v1669;
        let v4213: f64 = v0 * v4212;
        let v4214: f64 = v4213 * v896;
        let v4215: f64 = v4211 + v4214;
        let v4216: f64 = v1980 - v2540;
        let v4217: f64 = v0 * v4216;
        let v4218: f64 = v4217 * v1116;
        let v4219: f64 = v4215 + v4218;
        let v4220: f64 = v2276 + v2514;
        let v4221: f64 = v0 * v4220;
        let v4222: f64 = v4221 * v1280;
        let v4223: f64 = v4219 + v4222;
        let v4224: f64 = v730 - v2984;
        let v4225: f64 = v0 * v4224;
        let v4226: f64 = v4225 * v1395;
        let v4227: f64 = v1669 + v3727;
        let v4228: f64 = v0 * v4227;
        let v4229: f64 = v4228 * v618;
        let v4230: f64 = v4226 - v4229;
        let v4231: f64 = v4230 + v3968;
        let v4232: f64 = v2665 - v2964;
        let v4233: f64 = v0 * v4232;
        let v4234: f64 = v4233 * v1116;
        let v4235: f64 = v4231 + v4234;
        let v4236: f64 = v2803 + v2943;
        let v4237: f64 = v0 * v4236;
        let v4238: f64 = v4237 * v1280;
        let v4239: f64 = v4235 + v4238;
        let v4240: f64 = v981 - v3258;
        let v4241: f64 = v0 * v4240;
        let v4242: f64 = v4241 * v1395;
        let v4243: f64 = v1980 - v3784;
        let v4244: f64 = v0 * v4243;
        let v4245: f64 = v4244 * v618;
        let v4246: f64 = v4242 + v4245;
        let v4247: f64 = v2665 + v3783;
        let v4248: f64 = v0 * v4247;
        let v4249: f64 = v4248 * v896;
        let v4250: f64 = v4246 + v4249;
        let v4251: f64 = v4250 + v4079;
        let v4252: f64 = v3062 + v3226;
        let v4253: f64 = v0 * v4252;
        let v4254: f64 = v4253 * v1280;
        let v4255: f64 = v4251 + v4254;
        let v4256: f64 = v1179 - v3413;
        let v4257: f64 = v0 * v4256;
        let v4258: f64 = v4257 * v1395;
        let v4259: f64 = v2276 + v3827;
        let v4260: f64 = v0 * v4259;
        let v4261: f64 = v4260 * v618;
        let v4262: f64 = v4258 + v4261;
        let v4263: f64 = v2803 + v3826;
        let v4264: f64 = v0 * v4263;
        let v4265: f64 = v4264 * v896;
        let v4266: f64 = v4262 + v4265;
        let v4267: f64 = v3062 - v3393;
        let v4268: f64 = v0 * v4267;
        let v4269: f64 = v4268 * v1116;
        let v4270: f64 = v4266 + v4269;
        let v4271: f64 = v4270 - v4186;
        let v4272: f64 = v3864 - v2489;
        let v4273: f64 = v0 * v4272;
        let v4274: f64 = v4273 * v618;
        let v4275: f64 = v1319 + v3497;
        let v4276: f64 = v0 * v4275;
        let v4277: f64 = v4276 * v1395;
        let v4278: f64 = v4274 - v4277;
        let v4279: f64 = v3859 - v2920;
        let v4280: f64 = v0 * v4279;
        let v4281: f64 = v4280 * v896;
        let v4282: f64 = v4278 + v4281;
        let v4283: f64 = v3486 - v3177;
        let v4284: f64 = v0 * v4283;
        let v4285: f64 = v4284 * v1116;
        let v4286: f64 = v4282 + v4285;
        (
            v4104,
            v4120,
            v4136,
            v4152,
            v4170,
            v4191,
            v4207,
            v4223,
            v4239,
            v4255,
            v4271,
            v4286,
        )
    };
    [
        [v1394, v2614, v2997, v3285, v3446, v3501],
        [v3586, v3664, v3735, v3794, v3841, v3868],
        [v3884, v3900, v3917, v3939, v3960, v3981],
        [v3997, v4013, v4029, v4046, v4067, v4088],
        [v4104, v4120, v4136, v4152, v4170, v4191],
        [v4207, v4223, v4239, v4255, v4271, v4286],
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
/// Operation count: 650 floating-point operations, 10 trig calls.
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
        v130,
        v132,
        v135,
        v139,
        v141,
        v144,
        v146,
        v149,
        v151,
        v154,
        v158,
        v161,
        v162,
        v171,
        v176,
        v179,
        v180,
    ) = {
        let v0: f64 = q[1];
        let (v1, v3): (f64, f64) = ::armdyn_runtime::libm::sincos(v0);
        let v2: f64 = params[14];
        let v4: f64 = qd[0];
        let v5: f64 = v3 * v4;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = v2 * v7;
        let v9: f64 = params[15];
        let v10: f64 = v1 * v4;
        let v11: f64 = v10 * v6;
        let v12: f64 = v9 * v11;
        let v13: f64 = v8 - v12;
        let v14: f64 = params[16];
        let v15: f64 = v14 * v10;
        let v16: f64 = params[18];
        let v17: f64 = v16 * v5;
        let v18: f64 = v15 + v17;
        let v19: f64 = params[19];
        let v20: f64 = v19 * v6;
        let v21: f64 = v18 + v20;
        let v22: f64 = v5 * v21;
        let v23: f64 = v9 * v10;
        let v24: f64 = params[17];
        let v25: f64 = v24 * v5;
        let v26: f64 = v23 + v25;
        let v27: f64 = v16 * v6;
        let v28: f64 = v26 + v27;
        let v29: f64 = v6 * v28;
        let v30: f64 = v22 - v29;
        let v31: f64 = v13 + v30;
        let v32: f64 = params[12];
        let v33: f64 = 0.4318_f64;
        let v34: f64 = v33 * v11;
        let v35: f64 = v33 * v6;
        let v36: f64 = v10 * v35;
        let v37: f64 = v34 + v36;
        let v38: f64 = v32 * v37;
        let v39: f64 = params[13];
        let v40: f64 = v33 * v5;
        let v41: f64 = v10 * v40;
        let v42: f64 = v39 * v41;
        let v43: f64 = v38 - v42;
        let v44: f64 = v31 + v43;
        let v45: f64 = q[2];
        let (v49, v46): (f64, f64) = ::armdyn_runtime::libm::sincos(v45);
        let v47: f64 = params[24];
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
        let v59: f64 = params[26];
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
        let v72: f64 = params[28];
        let v73: f64 = v72 * v70;
        let v74: f64 = v71 - v73;
        let v75: f64 = params[29];
        let v76: f64 = v75 * v54;
        let v77: f64 = v74 + v76;
        let v78: f64 = v70 * v77;
        let v79: f64 = params[25];
        let v80: f64 = v79 * v65;
        let v81: f64 = params[27];
        let v82: f64 = v81 * v70;
        let v83: f64 = v80 - v82;
        let v84: f64 = v72 * v54;
        let v85: f64 = v83 + v84;
        let v86: f64 = v54 * v85;
        let v87: f64 = v78 + v86;
        let v88: f64 = v69 - v87;
        let v89: f64 = params[22];
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
        let v107: f64 = params[23];
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
        let (v124, v121): (f64, f64) = ::armdyn_runtime::libm::sincos(v120);
        let v122: f64 = params[34];
        let v123: f64 = v121 * v57;
        let v125: f64 = v124 * v65;
        let v126: f64 = v121 * v70;
        let v127: f64 = v125 + v126;
        let v128: f64 = qd[3];
        let v129: f64 = v127 * v128;
        let v130: f64 = v123 - v129;
        let v131: f64 = v122 * v130;
        let v132: f64 = params[35];
        let v133: f64 = v132 * v67;
        let v134: f64 = v131 - v133;
        let v135: f64 = params[36];
        let v136: f64 = v124 * v57;
        let v137: f64 = v121 * v65;
        let v138: f64 = v124 * v70;
        let v139: f64 = v137 - v138;
        let v140: f64 = v139 * v128;
        let v141: f64 = v136 + v140;
        let v142: f64 = v135 * v141;
        let v143: f64 = v134 + v142;
        let v144: f64 = v54 + v128;
        let v145: f64 = v135 * v139;
        let v146: f64 = params[38];
        let v147: f64 = v146 * v144;
        let v148: f64 = v145 + v147;
        let v149: f64 = params[39];
        let v150: f64 = v149 * v127;
        let v151: f64 = v148 + v150;
        let v152: f64 = v144 * v151;
        let v153: f64 = v132 * v139;
        let v154: f64 = params[37];
        let v155: f64 = v154 * v144;
        let v156: f64 = v153 + v155;
        let v157: f64 = v146 * v127;
        let v158: f64 = v156 + v157;
        let v159: f64 = v127 * v158;
        let v160: f64 = v152 - v159;
        let v161: f64 = v143 + v160;
        let v162: f64 = params[32];
        let v163: f64 = v49 * v41;
        let v164: f64 = v46 * v92;
        let v165: f64 = v163 - v164;
        let v166: f64 = v96 * v67;
        let v167: f64 = v70 * v112;
        let v168: f64 = v54 * v99;
        let v169: f64 = v167 + v168;
        let v170: f64 = v166 - v169;
        let v171: f64 = v165 + v170;
        let v172: f64 = v124 * v171;
        let v173: f64 = v121 * v116;
        let v174: f64 = v172 + v173;
        let v175: f64 = v33 * v130;
        let v176: f64 = v33 * v127;
        let v177: f64 = v144 * v176;
        let v178: f64 = v175 + v177;
        let v179: f64 = v174 + v178;
        let v180: f64 = v162 * v179;
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
            v130,
            v132,
            v135,
            v139,
            v141,
            v144,
            v146,
            v149,
            v151,
            v154,
            v158,
            v161,
            v162,
            v171,
            v176,
            v179,
            v180,
        )
    };
    let (
        v181,
        v186,
        v189,
        v191,
        v194,
        v199,
        v202,
        v204,
        v213,
        v215,
        v218,
        v220,
        v225,
        v228,
        v236,
        v244,
        v246,
        v248,
        v253,
        v256,
        v261,
        v264,
        v272,
        v274,
        v285,
        v298,
        v300,
        v303,
        v306,
        v309,
        v320,
        v327,
        v329,
        v332,
        v335,
        v336,
        v347,
        v351,
        v355,
        v360,
        v361,
    ) = {
        let v181: f64 = params[33];
        let v182: f64 = v127 * v176;
        let v183: f64 = v33 * v139;
        let v184: f64 = v139 * v183;
        let v185: f64 = v182 + v184;
        let v186: f64 = v105 - v185;
        let v187: f64 = v181 * v186;
        let v188: f64 = v180 - v187;
        let v189: f64 = v161 + v188;
        let v190: f64 = q[4];
        let (v194, v191): (f64, f64) = ::armdyn_runtime::libm::sincos(v190);
        let v192: f64 = params[44];
        let v193: f64 = v191 * v130;
        let v195: f64 = v194 * v67;
        let v196: f64 = v193 - v195;
        let v197: f64 = v191 * v144;
        let v198: f64 = v194 * v139;
        let v199: f64 = v197 - v198;
        let v200: f64 = qd[4];
        let v201: f64 = v199 * v200;
        let v202: f64 = v196 + v201;
        let v203: f64 = v192 * v202;
        let v204: f64 = params[45];
        let v205: f64 = v204 * v141;
        let v206: f64 = v203 - v205;
        let v207: f64 = params[46];
        let v208: f64 = v194 * v130;
        let v209: f64 = v191 * v67;
        let v210: f64 = v208 + v209;
        let v211: f64 = v191 * v139;
        let v212: f64 = v194 * v144;
        let v213: f64 = v211 + v212;
        let v214: f64 = v213 * v200;
        let v215: f64 = v210 + v214;
        let v216: f64 = v207 * v215;
        let v217: f64 = v206 - v216;
        let v218: f64 = v127 + v200;
        let v219: f64 = v207 * v213;
        let v220: f64 = params[48];
        let v221: f64 = v220 * v218;
        let v222: f64 = v219 - v221;
        let v223: f64 = params[49];
        let v224: f64 = v223 * v199;
        let v225: f64 = v222 + v224;
        let v226: f64 = v218 * v225;
        let v227: f64 = v204 * v213;
        let v228: f64 = params[47];
        let v229: f64 = v228 * v218;
        let v230: f64 = v227 - v229;
        let v231: f64 = v220 * v199;
        let v232: f64 = v230 + v231;
        let v233: f64 = v199 * v232;
        let v234: f64 = v226 + v233;
        let v235: f64 = v217 - v234;
        let v236: f64 = params[42];
        let v237: f64 = v191 * v186;
        let v238: f64 = v121 * v171;
        let v239: f64 = v124 * v116;
        let v240: f64 = v238 - v239;
        let v241: f64 = v144 * v183;
        let v242: f64 = v33 * v141;
        let v243: f64 = v241 - v242;
        let v244: f64 = v240 + v243;
        let v245: f64 = v194 * v244;
        let v246: f64 = v237 - v245;
        let v247: f64 = v236 * v246;
        let v248: f64 = params[43];
        let v249: f64 = v248 * v179;
        let v250: f64 = v247 + v249;
        let v251: f64 = v235 + v250;
        let v252: f64 = q[5];
        let (v256, v253): (f64, f64) = ::armdyn_runtime::libm::sincos(v252);
        let v254: f64 = params[54];
        let v255: f64 = v253 * v202;
        let v257: f64 = v256 * v141;
        let v258: f64 = v255 - v257;
        let v259: f64 = v256 * v213;
        let v260: f64 = v253 * v218;
        let v261: f64 = v259 + v260;
        let v262: f64 = qd[5];
        let v263: f64 = v261 * v262;
        let v264: f64 = v258 - v263;
        let v265: f64 = v254 * v264;
        let v266: f64 = params[55];
        let v267: f64 = v256 * v202;
        let v268: f64 = v253 * v141;
        let v269: f64 = v267 + v268;
        let v270: f64 = v253 * v213;
        let v271: f64 = v256 * v218;
        let v272: f64 = v270 - v271;
        let v273: f64 = v272 * v262;
        let v274: f64 = v269 + v273;
        let v275: f64 = v266 * v274;
        let v276: f64 = v265 - v275;
        let v277: f64 = params[56];
        let v278: f64 = v277 * v215;
        let v279: f64 = v276 - v278;
        let v280: f64 = v277 * v272;
        let v281: f64 = params[58];
        let v282: f64 = v281 * v261;
        let v283: f64 = v280 - v282;
        let v284: f64 = params[59];
        let v285: f64 = v199 + v262;
        let v286: f64 = v284 * v285;
        let v287: f64 = v283 + v286;
        let v288: f64 = v261 * v287;
        let v289: f64 = v266 * v272;
        let v290: f64 = params[57];
        let v291: f64 = v290 * v261;
        let v292: f64 = v289 - v291;
        let v293: f64 = v281 * v285;
        let v294: f64 = v292 + v293;
        let v295: f64 = v285 * v294;
        let v296: f64 = v288 + v295;
        let v297: f64 = v279 - v296;
        let v298: f64 = params[52];
        let v299: f64 = v298 * v246;
        let v300: f64 = params[53];
        let v301: f64 = v191 * v244;
        let v302: f64 = v194 * v186;
        let v303: f64 = v301 + v302;
        let v304: f64 = v256 * v303;
        let v305: f64 = v253 * v179;
        let v306: f64 = v304 + v305;
        let v307: f64 = v300 * v306;
        let v308: f64 = v299 + v307;
        let v309: f64 = v297 + v308;
        let v310: f64 = v253 * v309;
        let v311: f64 = v266 * v264;
        let v312: f64 = v290 * v274;
        let v313: f64 = v311 - v312;
        let v314: f64 = v281 * v215;
        let v315: f64 = v313 - v314;
        let v316: f64 = v254 * v272;
        let v317: f64 = v266 * v261;
        let v318: f64 = v316 - v317;
        let v319: f64 = v277 * v285;
        let v320: f64 = v318 + v319;
        let v321: f64 = v285 * v320;
        let v322: f64 = v272 * v287;
        let v323: f64 = v321 - v322;
        let v324: f64 = v315 + v323;
        let v325: f64 = v253 * v303;
        let v326: f64 = v256 * v179;
        let v327: f64 = v325 - v326;
        let v328: f64 = v300 * v327;
        let v329: f64 = params[51];
        let v330: f64 = v329 * v246;
        let v331: f64 = v328 - v330;
        let v332: f64 = v324 + v331;
        let v333: f64 = v256 * v332;
        let v334: f64 = v310 - v333;
        let v335: f64 = v251 + v334;
        let v336: f64 = v191 * v335;
        let v337: f64 = v207 * v202;
        let v338: f64 = v220 * v141;
        let v339: f64 = v337 - v338;
        let v340: f64 = v223 * v215;
        let v341: f64 = v339 - v340;
        let v342: f64 = v213 * v232;
        let v343: f64 = v192 * v213;
        let v344: f64 = v204 * v218;
        let v345: f64 = v343 - v344;
        let v346: f64 = v207 * v199;
        let v347: f64 = v345 + v346;
        let v348: f64 = v218 * v347;
        let v349: f64 = v342 + v348;
        let v350: f64 = v341 + v349;
        let v351: f64 = params[41];
        let v352: f64 = v351 * v179;
        let v353: f64 = v236 * v303;
        let v354: f64 = v352 + v353;
        let v355: f64 = v350 - v354;
        let v356: f64 = v277 * v264;
        let v357: f64 = v281 * v274;
        let v358: f64 = v356 - v357;
        let v359: f64 = v284 * v215;
        let v360: f64 = v358 - v359;
        let v361: f64 = v272 * v294;
        (
            v181,
            v186,
            v189,
            v191,
            v194,
            v199,
            v202,
            v204,
            v213,
            v215,
            v218,
            v220,
            v225,
            v228,
            v236,
            v244,
            v246,
            v248,
            v253,
            v256,
            v261,
            v264,
            v272,
            v274,
            v285,
            v298,
            v300,
            v303,
            v306,
            v309,
            v320,
            v327,
            v329,
            v332,
            v335,
            v336,
            v347,
            v351,
            v355,
            v360,
            v361,
        )
    };
    let (
        v368,
        v369,
        v373,
        v376,
        v385,
        v438,
        v440,
        v452,
        v476,
        v481,
        v505,
        v525,
        v528,
        v530,
        v533,
        v534,
        v535,
        v536,
        v537,
        v540,
        v541,
        v542,
    ) = {
        let v362: f64 = v261 * v320;
        let v363: f64 = v361 + v362;
        let v364: f64 = v360 + v363;
        let v365: f64 = v329 * v306;
        let v366: f64 = v298 * v327;
        let v367: f64 = v365 + v366;
        let v368: f64 = v364 - v367;
        let v369: f64 = v355 + v368;
        let v370: f64 = v194 * v369;
        let v371: f64 = v336 - v370;
        let v372: f64 = v189 + v371;
        let v373: f64 = params[30];
        let v374: f64 = v373 * v179;
        let v375: f64 = v130 * v162;
        let v376: f64 = params[31];
        let v377: f64 = v67 * v376;
        let v378: f64 = v375 + v377;
        let v379: f64 = v127 * v376;
        let v380: f64 = v139 * v181;
        let v381: f64 = v379 - v380;
        let v382: f64 = v139 * v381;
        let v383: f64 = v144 * v181;
        let v384: f64 = v127 * v162;
        let v385: f64 = v383 - v384;
        let v386: f64 = v144 * v385;
        let v387: f64 = v382 - v386;
        let v388: f64 = v378 + v387;
        let v389: f64 = v374 + v388;
        let v390: f64 = params[50];
        let v391: f64 = v390 * v327;
        let v392: f64 = v215 * v298;
        let v393: f64 = v274 * v300;
        let v394: f64 = v392 - v393;
        let v395: f64 = v272 * v298;
        let v396: f64 = v261 * v329;
        let v397: f64 = v395 + v396;
        let v398: f64 = v261 * v397;
        let v399: f64 = v285 * v329;
        let v400: f64 = v272 * v300;
        let v401: f64 = v399 - v400;
        let v402: f64 = v285 * v401;
        let v403: f64 = v398 + v402;
        let v404: f64 = v394 - v403;
        let v405: f64 = v391 + v404;
        let v406: f64 = v256 * v405;
        let v407: f64 = v390 * v306;
        let v408: f64 = v215 * v329;
        let v409: f64 = v264 * v300;
        let v410: f64 = v408 + v409;
        let v411: f64 = v261 * v300;
        let v412: f64 = v285 * v298;
        let v413: f64 = v411 + v412;
        let v414: f64 = v285 * v413;
        let v415: f64 = v272 * v397;
        let v416: f64 = v414 + v415;
        let v417: f64 = v410 + v416;
        let v418: f64 = v407 + v417;
        let v419: f64 = v253 * v418;
        let v420: f64 = v406 - v419;
        let v421: f64 = params[40];
        let v422: f64 = v421 * v179;
        let v423: f64 = v215 * v351;
        let v424: f64 = v202 * v248;
        let v425: f64 = v423 + v424;
        let v426: f64 = v218 * v248;
        let v427: f64 = v199 * v236;
        let v428: f64 = v426 + v427;
        let v429: f64 = v199 * v428;
        let v430: f64 = v213 * v236;
        let v431: f64 = v218 * v351;
        let v432: f64 = v430 + v431;
        let v433: f64 = v213 * v432;
        let v434: f64 = v429 + v433;
        let v435: f64 = v425 + v434;
        let v436: f64 = v422 + v435;
        let v437: f64 = v420 - v436;
        let v438: f64 = v389 - v437;
        let v439: f64 = v33 * v438;
        let v440: f64 = v372 + v439;
        let v441: f64 = v121 * v440;
        let v442: f64 = v135 * v130;
        let v443: f64 = v146 * v67;
        let v444: f64 = v442 - v443;
        let v445: f64 = v149 * v141;
        let v446: f64 = v444 + v445;
        let v447: f64 = v139 * v158;
        let v448: f64 = v122 * v139;
        let v449: f64 = v132 * v144;
        let v450: f64 = v448 + v449;
        let v451: f64 = v135 * v127;
        let v452: f64 = v450 + v451;
        let v453: f64 = v144 * v452;
        let v454: f64 = v447 - v453;
        let v455: f64 = v446 + v454;
        let v456: f64 = v376 * v186;
        let v457: f64 = v162 * v244;
        let v458: f64 = v456 - v457;
        let v459: f64 = v455 + v458;
        let v460: f64 = v204 * v202;
        let v461: f64 = v228 * v141;
        let v462: f64 = v460 - v461;
        let v463: f64 = v220 * v215;
        let v464: f64 = v462 - v463;
        let v465: f64 = v199 * v347;
        let v466: f64 = v213 * v225;
        let v467: f64 = v465 - v466;
        let v468: f64 = v464 + v467;
        let v469: f64 = v248 * v303;
        let v470: f64 = v351 * v246;
        let v471: f64 = v469 - v470;
        let v472: f64 = v468 + v471;
        let v473: f64 = v256 * v309;
        let v474: f64 = v253 * v332;
        let v475: f64 = v473 + v474;
        let v476: f64 = v472 + v475;
        let v477: f64 = v459 - v476;
        let v478: f64 = v373 * v244;
        let v479: f64 = v139 * v162;
        let v480: f64 = v144 * v376;
        let v481: f64 = v479 - v480;
        let v482: f64 = v144 * v481;
        let v483: f64 = v127 * v381;
        let v484: f64 = v482 - v483;
        let v485: f64 = v67 * v181;
        let v486: f64 = v141 * v162;
        let v487: f64 = v485 + v486;
        let v488: f64 = v484 - v487;
        let v489: f64 = v478 + v488;
        let v490: f64 = v421 * v303;
        let v491: f64 = v215 * v236;
        let v492: f64 = v141 * v248;
        let v493: f64 = v491 - v492;
        let v494: f64 = v218 * v432;
        let v495: f64 = v199 * v351;
        let v496: f64 = v213 * v248;
        let v497: f64 = v495 - v496;
        let v498: f64 = v199 * v497;
        let v499: f64 = v494 + v498;
        let v500: f64 = v493 - v499;
        let v501: f64 = v490 + v500;
        let v502: f64 = v253 * v405;
        let v503: f64 = v256 * v418;
        let v504: f64 = v502 + v503;
        let v505: f64 = v501 + v504;
        let v506: f64 = v191 * v505;
        let v507: f64 = v421 * v246;
        let v508: f64 = v202 * v236;
        let v509: f64 = v141 * v351;
        let v510: f64 = v508 + v509;
        let v511: f64 = v213 * v497;
        let v512: f64 = v218 * v428;
        let v513: f64 = v511 - v512;
        let v514: f64 = v510 + v513;
        let v515: f64 = v507 + v514;
        let v516: f64 = v390 * v246;
        let v517: f64 = v264 * v298;
        let v518: f64 = v274 * v329;
        let v519: f64 = v517 + v518;
        let v520: f64 = v272 * v401;
        let v521: f64 = v261 * v413;
        let v522: f64 = v520 - v521;
        let v523: f64 = v519 + v522;
        let v524: f64 = v516 + v523;
        let v525: f64 = v515 + v524;
        let v526: f64 = v194 * v525;
        let v527: f64 = v506 - v526;
        let v528: f64 = v489 + v527;
        let v529: f64 = v33 * v528;
        let v530: f64 = v477 - v529;
        let v531: f64 = v124 * v530;
        let v532: f64 = v441 + v531;
        let v533: f64 = v119 + v532;
        let v534: f64 = params[20];
        let v535: f64 = v534 * v105;
        let v536: f64 = v57 * v89;
        let v537: f64 = params[21];
        let v538: f64 = v54 * v537;
        let v539: f64 = v65 * v107;
        let v540: f64 = v538 - v539;
        let v541: f64 = v65 * v540;
        let v542: f64 = v70 * v107;
        (
            v368,
            v369,
            v373,
            v376,
            v385,
            v438,
            v440,
            v452,
            v476,
            v481,
            v505,
            v525,
            v528,
            v530,
            v533,
            v534,
            v535,
            v536,
            v537,
            v540,
            v541,
            v542,
        )
    };
    let (v598, v676, v721, v722, v723) = {
        let v543: f64 = v54 * v89;
        let v544: f64 = v542 + v543;
        let v545: f64 = v70 * v544;
        let v546: f64 = v541 - v545;
        let v547: f64 = v536 + v546;
        let v548: f64 = v535 + v547;
        let v549: f64 = v373 * v186;
        let v550: f64 = v141 * v376;
        let v551: f64 = v130 * v181;
        let v552: f64 = v550 - v551;
        let v553: f64 = v127 * v385;
        let v554: f64 = v139 * v481;
        let v555: f64 = v553 - v554;
        let v556: f64 = v552 + v555;
        let v557: f64 = v549 + v556;
        let v558: f64 = v194 * v505;
        let v559: f64 = v191 * v525;
        let v560: f64 = v558 + v559;
        let v561: f64 = v557 + v560;
        let v562: f64 = v548 + v561;
        let v563: f64 = v96 * v562;
        let v564: f64 = v533 + v563;
        let v565: f64 = v46 * v564;
        let v566: f64 = v59 * v57;
        let v567: f64 = v75 * v67;
        let v568: f64 = v566 - v567;
        let v569: f64 = v65 * v85;
        let v570: f64 = v47 * v65;
        let v571: f64 = v79 * v70;
        let v572: f64 = v570 - v571;
        let v573: f64 = v59 * v54;
        let v574: f64 = v572 + v573;
        let v575: f64 = v70 * v574;
        let v576: f64 = v569 + v575;
        let v577: f64 = v568 + v576;
        let v578: f64 = v537 * v116;
        let v579: f64 = v89 * v171;
        let v580: f64 = v578 + v579;
        let v581: f64 = v577 - v580;
        let v582: f64 = v132 * v130;
        let v583: f64 = v154 * v67;
        let v584: f64 = v582 - v583;
        let v585: f64 = v146 * v141;
        let v586: f64 = v584 + v585;
        let v587: f64 = v127 * v452;
        let v588: f64 = v139 * v151;
        let v589: f64 = v587 - v588;
        let v590: f64 = v586 + v589;
        let v591: f64 = v181 * v244;
        let v592: f64 = v376 * v179;
        let v593: f64 = v591 - v592;
        let v594: f64 = v590 + v593;
        let v595: f64 = v194 * v335;
        let v596: f64 = v191 * v369;
        let v597: f64 = v595 + v596;
        let v598: f64 = v594 + v597;
        let v599: f64 = v581 + v598;
        let v600: f64 = v124 * v528;
        let v601: f64 = v121 * v438;
        let v602: f64 = v600 - v601;
        let v603: f64 = v534 * v116;
        let v604: f64 = v67 * v537;
        let v605: f64 = v57 * v107;
        let v606: f64 = v604 + v605;
        let v607: f64 = v54 * v544;
        let v608: f64 = v65 * v89;
        let v609: f64 = v70 * v537;
        let v610: f64 = v608 + v609;
        let v611: f64 = v65 * v610;
        let v612: f64 = v607 + v611;
        let v613: f64 = v606 + v612;
        let v614: f64 = v603 + v613;
        let v615: f64 = v602 - v614;
        let v616: f64 = v98 * v615;
        let v617: f64 = v534 * v171;
        let v618: f64 = v67 * v89;
        let v619: f64 = v70 * v610;
        let v620: f64 = v54 * v540;
        let v621: f64 = v619 + v620;
        let v622: f64 = v618 - v621;
        let v623: f64 = v617 + v622;
        let v624: f64 = v121 * v528;
        let v625: f64 = v124 * v438;
        let v626: f64 = v624 + v625;
        let v627: f64 = v623 + v626;
        let v628: f64 = v96 * v627;
        let v629: f64 = v616 - v628;
        let v630: f64 = v599 + v629;
        let v631: f64 = v49 * v630;
        let v632: f64 = v565 - v631;
        let v633: f64 = v44 + v632;
        let v634: f64 = v1 * v633;
        let v635: f64 = v9 * v7;
        let v636: f64 = v24 * v11;
        let v637: f64 = v635 - v636;
        let v638: f64 = v2 * v10;
        let v639: f64 = v9 * v5;
        let v640: f64 = v638 + v639;
        let v641: f64 = v14 * v6;
        let v642: f64 = v640 + v641;
        let v643: f64 = v6 * v642;
        let v644: f64 = v10 * v21;
        let v645: f64 = v643 - v644;
        let v646: f64 = v637 + v645;
        let v647: f64 = v39 * v92;
        let v648: f64 = params[11];
        let v649: f64 = v648 * v37;
        let v650: f64 = v647 + v649;
        let v651: f64 = v646 - v650;
        let v652: f64 = v49 * v564;
        let v653: f64 = v46 * v630;
        let v654: f64 = v652 + v653;
        let v655: f64 = v651 + v654;
        let v656: f64 = params[10];
        let v657: f64 = v656 * v37;
        let v658: f64 = v7 * v32;
        let v659: f64 = v11 * v648;
        let v660: f64 = v658 + v659;
        let v661: f64 = v6 * v648;
        let v662: f64 = v10 * v39;
        let v663: f64 = v661 - v662;
        let v664: f64 = v10 * v663;
        let v665: f64 = v5 * v39;
        let v666: f64 = v6 * v32;
        let v667: f64 = v665 - v666;
        let v668: f64 = v5 * v667;
        let v669: f64 = v664 - v668;
        let v670: f64 = v660 + v669;
        let v671: f64 = v657 + v670;
        let v672: f64 = v671 - v615;
        let v673: f64 = v33 * v672;
        let v674: f64 = v655 - v673;
        let v675: f64 = v3 * v674;
        let v676: f64 = v634 + v675;
        let v677: f64 = v14 * v7;
        let v678: f64 = v16 * v11;
        let v679: f64 = v677 - v678;
        let v680: f64 = v10 * v28;
        let v681: f64 = v5 * v642;
        let v682: f64 = v680 - v681;
        let v683: f64 = v679 + v682;
        let v684: f64 = v648 * v41;
        let v685: f64 = v32 * v92;
        let v686: f64 = v684 + v685;
        let v687: f64 = v683 + v686;
        let v688: f64 = v79 * v57;
        let v689: f64 = v72 * v67;
        let v690: f64 = v688 - v689;
        let v691: f64 = v54 * v574;
        let v692: f64 = v65 * v77;
        let v693: f64 = v691 - v692;
        let v694: f64 = v690 + v693;
        let v695: f64 = v107 * v171;
        let v696: f64 = v537 * v105;
        let v697: f64 = v695 - v696;
        let v698: f64 = v694 + v697;
        let v699: f64 = v124 * v440;
        let v700: f64 = v121 * v530;
        let v701: f64 = v699 - v700;
        let v702: f64 = v698 + v701;
        let v703: f64 = v98 * v562;
        let v704: f64 = v702 - v703;
        let v705: f64 = v687 - v704;
        let v706: f64 = v656 * v41;
        let v707: f64 = v6 * v667;
        let v708: f64 = v10 * v32;
        let v709: f64 = v5 * v648;
        let v710: f64 = v708 - v709;
        let v711: f64 = v10 * v710;
        let v712: f64 = v707 - v711;
        let v713: f64 = v7 * v39;
        let v714: f64 = v712 - v713;
        let v715: f64 = v706 + v714;
        let v716: f64 = v49 * v627;
        let v717: f64 = v46 * v562;
        let v718: f64 = v716 + v717;
        let v719: f64 = v715 + v718;
        let v720: f64 = v33 * v719;
        let v721: f64 = v705 + v720;
        let v722: f64 = -v704;
        let v723: f64 = -v476;
        (v598, v676, v721, v722, v723)
    };
    [v676, v721, v722, v598, v723, v368]
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
/// Operation count: 125 floating-point operations, 10 trig calls.
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
    let v2: f64 = params[52];
    let v3: f64 = v1 * v2;
    let v4: f64 = q[5];
    let (v5, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = v3 * v5;
    let v7: f64 = params[41];
    let v8: f64 = v1 * v7;
    let v9: f64 = params[51];
    let v10: f64 = v1 * v9;
    let v12: f64 = v10 * v11;
    let v13: f64 = v8 + v12;
    let v14: f64 = v6 - v13;
    let v15: f64 = q[4];
    let (v16, v38): (f64, f64) = ::armdyn_runtime::libm::sincos(v15);
    let v17: f64 = v14 * v16;
    let v18: f64 = 4.235958_f64;
    let v19: f64 = params[50];
    let v20: f64 = v18 * v19;
    let v21: f64 = params[40];
    let v22: f64 = v18 * v21;
    let v23: f64 = v20 + v22;
    let v24: f64 = params[32];
    let v25: f64 = v1 * v24;
    let v26: f64 = v23 + v25;
    let v27: f64 = params[30];
    let v28: f64 = v18 * v27;
    let v29: f64 = v26 + v28;
    let v30: f64 = params[23];
    let v31: f64 = v1 * v30;
    let v32: f64 = v29 + v31;
    let v33: f64 = params[53];
    let v34: f64 = v1 * v33;
    let v35: f64 = params[43];
    let v36: f64 = v1 * v35;
    let v37: f64 = v34 + v36;
    let v39: f64 = v37 * v38;
    let v40: f64 = v32 + v39;
    let v41: f64 = v17 - v40;
    let v42: f64 = q[2];
    let (v82, v43): (f64, f64) = ::armdyn_runtime::libm::sincos(v42);
    let v44: f64 = v41 * v43;
    let v45: f64 = params[12];
    let v46: f64 = v1 * v45;
    let v47: f64 = v44 - v46;
    let v48: f64 = params[42];
    let v49: f64 = v1 * v48;
    let v50: f64 = params[33];
    let v51: f64 = v1 * v50;
    let v52: f64 = v49 - v51;
    let v53: f64 = v3 * v11;
    let v54: f64 = v52 + v53;
    let v55: f64 = v10 * v5;
    let v56: f64 = v54 + v55;
    let v57: f64 = q[3];
    let (v58, v79): (f64, f64) = ::armdyn_runtime::libm::sincos(v57);
    let v59: f64 = v56 * v58;
    let v60: f64 = 0.199143_f64;
    let v61: f64 = v60 * v19;
    let v62: f64 = v60 * v21;
    let v63: f64 = v61 + v62;
    let v64: f64 = v60 * v27;
    let v65: f64 = v63 + v64;
    let v66: f64 = params[21];
    let v67: f64 = v1 * v66;
    let v68: f64 = v65 + v67;
    let v69: f64 = params[20];
    let v70: f64 = v60 * v69;
    let v71: f64 = v68 + v70;
    let v72: f64 = v59 - v71;
    let v73: f64 = v37 * v16;
    let v74: f64 = params[31];
    let v75: f64 = v1 * v74;
    let v76: f64 = v73 - v75;
    let v77: f64 = v14 * v38;
    let v78: f64 = v76 + v77;
    let v80: f64 = v78 * v79;
    let v81: f64 = v72 + v80;
    let v83: f64 = v81 * v82;
    let v84: f64 = v47 + v83;
    let v85: f64 = q[1];
    let (v86, v112): (f64, f64) = ::armdyn_runtime::libm::sincos(v85);
    let v87: f64 = v84 * v86;
    let v88: f64 = v23 + v28;
    let v89: f64 = v18 * v69;
    let v90: f64 = v88 + v89;
    let v91: f64 = params[11];
    let v92: f64 = v1 * v91;
    let v93: f64 = v90 + v92;
    let v94: f64 = params[10];
    let v95: f64 = v18 * v94;
    let v96: f64 = v93 + v95;
    let v97: f64 = v41 * v82;
    let v98: f64 = v96 + v97;
    let v99: f64 = v51 - v49;
    let v100: f64 = v99 - v53;
    let v101: f64 = v100 - v55;
    let v102: f64 = v101 * v58;
    let v103: f64 = v71 + v102;
    let v104: f64 = v75 - v73;
    let v105: f64 = v13 - v6;
    let v106: f64 = v105 * v38;
    let v107: f64 = v104 + v106;
    let v108: f64 = v107 * v79;
    let v109: f64 = v103 + v108;
    let v110: f64 = v109 * v43;
    let v111: f64 = v98 + v110;
    let v113: f64 = v111 * v112;
    let v114: f64 = v87 + v113;
    let v115: f64 = v97 + v110;
    let v116: f64 = v115 * v112;
    let v117: f64 = v44 + v83;
    let v118: f64 = v117 * v86;
    let v119: f64 = v116 + v118;
    let v120: f64 = v101 * v82;
    let v121: f64 = v120 * v112;
    let v122: f64 = v101 * v43;
    let v123: f64 = v122 * v86;
    let v124: f64 = v121 + v123;
    let v125: f64 = v124 * v79;
    let v126: f64 = v78 * v82;
    let v127: f64 = v126 * v112;
    let v128: f64 = v78 * v43;
    let v129: f64 = v128 * v86;
    let v130: f64 = v127 + v129;
    let v131: f64 = v130 * v58;
    let v132: f64 = v125 + v131;
    let v133: f64 = v106 - v73;
    let v134: f64 = v133 * v43;
    let v135: f64 = v17 - v39;
    let v136: f64 = v135 * v79;
    let v137: f64 = v136 * v82;
    let v138: f64 = v134 + v137;
    let v139: f64 = v138 * v112;
    let v140: f64 = v136 * v43;
    let v141: f64 = v73 + v77;
    let v142: f64 = v141 * v82;
    let v143: f64 = v140 + v142;
    let v144: f64 = v143 * v86;
    let v145: f64 = v139 + v144;
    let v146: f64 = v6 - v12;
    let v147: f64 = v146 * v58;
    let v148: f64 = v53 + v55;
    let v149: f64 = v148 * v38;
    let v150: f64 = v149 * v79;
    let v151: f64 = v147 - v150;
    let v152: f64 = v151 * v82;
    let v153: f64 = v148 * v16;
    let v154: f64 = v153 * v43;
    let v155: f64 = v152 - v154;
    let v156: f64 = v155 * v112;
    let v157: f64 = v153 * v82;
    let v158: f64 = v151 * v43;
    let v159: f64 = v157 + v158;
    let v160: f64 = v159 * v86;
    let v161: f64 = v156 + v160;
    [v0, v114, v119, v132, v145, v161]
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
/// Operation count: 690 floating-point operations, 10 trig calls.
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
        v122,
        v128,
        v130,
        v135,
        v139,
        v142,
        v144,
        v145,
        v147,
        v152,
        v155,
        v157,
        v159,
        v162,
        v168,
        v170,
        v173,
        v175,
        v178,
        v180,
        v183,
        v187,
        v190,
        v191,
        v192,
    ) = {
        let v0: f64 = params[7];
        let v1: f64 = qdd[0];
        let v2: f64 = v0 * v1;
        let v3: f64 = q[1];
        let (v4, v7): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
        let v5: f64 = params[14];
        let v6: f64 = v4 * v1;
        let v8: f64 = qd[0];
        let v9: f64 = v7 * v8;
        let v10: f64 = qd[1];
        let v11: f64 = v9 * v10;
        let v12: f64 = v6 + v11;
        let v13: f64 = v5 * v12;
        let v14: f64 = params[15];
        let v15: f64 = v7 * v1;
        let v16: f64 = v4 * v8;
        let v17: f64 = v16 * v10;
        let v18: f64 = v15 - v17;
        let v19: f64 = v14 * v18;
        let v20: f64 = v13 + v19;
        let v21: f64 = params[16];
        let v22: f64 = qdd[1];
        let v23: f64 = v21 * v22;
        let v24: f64 = v20 + v23;
        let v25: f64 = v21 * v16;
        let v26: f64 = params[18];
        let v27: f64 = v26 * v9;
        let v28: f64 = v25 + v27;
        let v29: f64 = params[19];
        let v30: f64 = v29 * v10;
        let v31: f64 = v28 + v30;
        let v32: f64 = v9 * v31;
        let v33: f64 = v14 * v16;
        let v34: f64 = params[17];
        let v35: f64 = v34 * v9;
        let v36: f64 = v33 + v35;
        let v37: f64 = v26 * v10;
        let v38: f64 = v36 + v37;
        let v39: f64 = v10 * v38;
        let v40: f64 = v32 - v39;
        let v41: f64 = v24 + v40;
        let v42: f64 = params[12];
        let v43: f64 = 0.4318_f64;
        let v44: f64 = v43 * v10;
        let v45: f64 = v16 * v44;
        let v46: f64 = v43 * v18;
        let v47: f64 = v45 - v46;
        let v48: f64 = v42 * v47;
        let v49: f64 = params[13];
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
        let (v64, v61): (f64, f64) = ::armdyn_runtime::libm::sincos(v60);
        let v62: f64 = params[24];
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
        let v74: f64 = params[25];
        let v75: f64 = qdd[2];
        let v76: f64 = v22 + v75;
        let v77: f64 = v74 * v76;
        let v78: f64 = v73 - v77;
        let v79: f64 = params[26];
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
        let v92: f64 = params[28];
        let v93: f64 = v92 * v90;
        let v94: f64 = v91 - v93;
        let v95: f64 = params[29];
        let v96: f64 = v95 * v69;
        let v97: f64 = v94 + v96;
        let v98: f64 = v90 * v97;
        let v99: f64 = v74 * v85;
        let v100: f64 = params[27];
        let v101: f64 = v100 * v90;
        let v102: f64 = v99 - v101;
        let v103: f64 = v92 * v69;
        let v104: f64 = v102 + v103;
        let v105: f64 = v69 * v104;
        let v106: f64 = v98 + v105;
        let v107: f64 = v89 - v106;
        let v108: f64 = params[22];
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
        let v130: f64 = params[23];
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
        let (v147, v144): (f64, f64) = ::armdyn_runtime::libm::sincos(v143);
        let v145: f64 = params[34];
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
        let v157: f64 = params[35];
        let v158: f64 = qdd[3];
        let v159: f64 = v87 + v158;
        let v160: f64 = v157 * v159;
        let v161: f64 = v156 + v160;
        let v162: f64 = params[36];
        let v163: f64 = v147 * v72;
        let v164: f64 = v144 * v76;
        let v165: f64 = v163 + v164;
        let v166: f64 = v144 * v85;
        let v167: f64 = v147 * v90;
        let v168: f64 = v166 - v167;
        let v169: f64 = v168 * v153;
        let v170: f64 = v165 + v169;
        let v171: f64 = v162 * v170;
        let v172: f64 = v161 + v171;
        let v173: f64 = v69 + v153;
        let v174: f64 = v162 * v168;
        let v175: f64 = params[38];
        let v176: f64 = v175 * v173;
        let v177: f64 = v174 + v176;
        let v178: f64 = params[39];
        let v179: f64 = v178 * v152;
        let v180: f64 = v177 + v179;
        let v181: f64 = v173 * v180;
        let v182: f64 = v157 * v168;
        let v183: f64 = params[37];
        let v184: f64 = v183 * v173;
        let v185: f64 = v182 + v184;
        let v186: f64 = v175 * v152;
        let v187: f64 = v185 + v186;
        let v188: f64 = v152 * v187;
        let v189: f64 = v181 - v188;
        let v190: f64 = v172 + v189;
        let v191: f64 = params[32];
        let v192: f64 = v61 * v114;
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
            v122,
            v128,
            v130,
            v135,
            v139,
            v142,
            v144,
            v145,
            v147,
            v152,
            v155,
            v157,
            v159,
            v162,
            v168,
            v170,
            v173,
            v175,
            v178,
            v180,
            v183,
            v187,
            v190,
            v191,
            v192,
        )
    };
    let (
        v200,
        v208,
        v210,
        v215,
        v218,
        v220,
        v223,
        v228,
        v231,
        v233,
        v235,
        v244,
        v246,
        v249,
        v251,
        v256,
        v259,
        v267,
        v275,
        v277,
        v279,
        v284,
        v287,
        v292,
        v295,
        v303,
        v305,
        v308,
        v310,
        v314,
        v317,
        v318,
        v327,
        v331,
        v333,
        v336,
        v339,
        v342,
        v353,
        v360,
        v362,
        v365,
        v368,
        v369,
        v380,
        v383,
        v384,
        v385,
    ) = {
        let v193: f64 = v64 * v56;
        let v194: f64 = v192 + v193;
        let v195: f64 = v117 * v87;
        let v196: f64 = v90 * v135;
        let v197: f64 = v69 * v122;
        let v198: f64 = v196 + v197;
        let v199: f64 = v195 + v198;
        let v200: f64 = v194 - v199;
        let v201: f64 = v147 * v200;
        let v202: f64 = v144 * v139;
        let v203: f64 = v201 - v202;
        let v204: f64 = v43 * v155;
        let v205: f64 = v43 * v152;
        let v206: f64 = v173 * v205;
        let v207: f64 = v204 + v206;
        let v208: f64 = v203 + v207;
        let v209: f64 = v191 * v208;
        let v210: f64 = params[33];
        let v211: f64 = v152 * v205;
        let v212: f64 = v43 * v168;
        let v213: f64 = v168 * v212;
        let v214: f64 = v211 + v213;
        let v215: f64 = v128 - v214;
        let v216: f64 = v210 * v215;
        let v217: f64 = v209 - v216;
        let v218: f64 = v190 + v217;
        let v219: f64 = q[4];
        let (v223, v220): (f64, f64) = ::armdyn_runtime::libm::sincos(v219);
        let v221: f64 = params[44];
        let v222: f64 = v220 * v155;
        let v224: f64 = v223 * v159;
        let v225: f64 = v222 + v224;
        let v226: f64 = v220 * v173;
        let v227: f64 = v223 * v168;
        let v228: f64 = v226 - v227;
        let v229: f64 = qd[4];
        let v230: f64 = v228 * v229;
        let v231: f64 = v225 + v230;
        let v232: f64 = v221 * v231;
        let v233: f64 = params[45];
        let v234: f64 = qdd[4];
        let v235: f64 = v170 + v234;
        let v236: f64 = v233 * v235;
        let v237: f64 = v232 - v236;
        let v238: f64 = params[46];
        let v239: f64 = v220 * v159;
        let v240: f64 = v223 * v155;
        let v241: f64 = v239 - v240;
        let v242: f64 = v220 * v168;
        let v243: f64 = v223 * v173;
        let v244: f64 = v242 + v243;
        let v245: f64 = v244 * v229;
        let v246: f64 = v241 - v245;
        let v247: f64 = v238 * v246;
        let v248: f64 = v237 + v247;
        let v249: f64 = v152 + v229;
        let v250: f64 = v238 * v244;
        let v251: f64 = params[48];
        let v252: f64 = v251 * v249;
        let v253: f64 = v250 - v252;
        let v254: f64 = params[49];
        let v255: f64 = v254 * v228;
        let v256: f64 = v253 + v255;
        let v257: f64 = v249 * v256;
        let v258: f64 = v233 * v244;
        let v259: f64 = params[47];
        let v260: f64 = v259 * v249;
        let v261: f64 = v258 - v260;
        let v262: f64 = v251 * v228;
        let v263: f64 = v261 + v262;
        let v264: f64 = v228 * v263;
        let v265: f64 = v257 + v264;
        let v266: f64 = v248 - v265;
        let v267: f64 = params[42];
        let v268: f64 = v220 * v215;
        let v269: f64 = v144 * v200;
        let v270: f64 = v147 * v139;
        let v271: f64 = v269 + v270;
        let v272: f64 = v173 * v212;
        let v273: f64 = v43 * v170;
        let v274: f64 = v272 - v273;
        let v275: f64 = v271 + v274;
        let v276: f64 = v223 * v275;
        let v277: f64 = v268 - v276;
        let v278: f64 = v267 * v277;
        let v279: f64 = params[43];
        let v280: f64 = v279 * v208;
        let v281: f64 = v278 + v280;
        let v282: f64 = v266 + v281;
        let v283: f64 = q[5];
        let (v287, v284): (f64, f64) = ::armdyn_runtime::libm::sincos(v283);
        let v285: f64 = params[54];
        let v286: f64 = v284 * v231;
        let v288: f64 = v287 * v235;
        let v289: f64 = v286 - v288;
        let v290: f64 = v287 * v244;
        let v291: f64 = v284 * v249;
        let v292: f64 = v290 + v291;
        let v293: f64 = qd[5];
        let v294: f64 = v292 * v293;
        let v295: f64 = v289 - v294;
        let v296: f64 = v285 * v295;
        let v297: f64 = params[55];
        let v298: f64 = v287 * v231;
        let v299: f64 = v284 * v235;
        let v300: f64 = v298 + v299;
        let v301: f64 = v284 * v244;
        let v302: f64 = v287 * v249;
        let v303: f64 = v301 - v302;
        let v304: f64 = v303 * v293;
        let v305: f64 = v300 + v304;
        let v306: f64 = v297 * v305;
        let v307: f64 = v296 - v306;
        let v308: f64 = params[56];
        let v309: f64 = qdd[5];
        let v310: f64 = v246 + v309;
        let v311: f64 = v308 * v310;
        let v312: f64 = v307 + v311;
        let v313: f64 = v308 * v303;
        let v314: f64 = params[58];
        let v315: f64 = v314 * v292;
        let v316: f64 = v313 - v315;
        let v317: f64 = params[59];
        let v318: f64 = v228 + v293;
        let v319: f64 = v317 * v318;
        let v320: f64 = v316 + v319;
        let v321: f64 = v292 * v320;
        let v322: f64 = v297 * v303;
        let v323: f64 = params[57];
        let v324: f64 = v323 * v292;
        let v325: f64 = v322 - v324;
        let v326: f64 = v314 * v318;
        let v327: f64 = v325 + v326;
        let v328: f64 = v318 * v327;
        let v329: f64 = v321 + v328;
        let v330: f64 = v312 - v329;
        let v331: f64 = params[52];
        let v332: f64 = v331 * v277;
        let v333: f64 = params[53];
        let v334: f64 = v220 * v275;
        let v335: f64 = v223 * v215;
        let v336: f64 = v334 + v335;
        let v337: f64 = v287 * v336;
        let v338: f64 = v284 * v208;
        let v339: f64 = v337 + v338;
        let v340: f64 = v333 * v339;
        let v341: f64 = v332 + v340;
        let v342: f64 = v330 + v341;
        let v343: f64 = v284 * v342;
        let v344: f64 = v297 * v295;
        let v345: f64 = v323 * v305;
        let v346: f64 = v344 - v345;
        let v347: f64 = v314 * v310;
        let v348: f64 = v346 + v347;
        let v349: f64 = v285 * v303;
        let v350: f64 = v297 * v292;
        let v351: f64 = v349 - v350;
        let v352: f64 = v308 * v318;
        let v353: f64 = v351 + v352;
        let v354: f64 = v318 * v353;
        let v355: f64 = v303 * v320;
        let v356: f64 = v354 - v355;
        let v357: f64 = v348 + v356;
        let v358: f64 = v284 * v336;
        let v359: f64 = v287 * v208;
        let v360: f64 = v358 - v359;
        let v361: f64 = v333 * v360;
        let v362: f64 = params[51];
        let v363: f64 = v362 * v277;
        let v364: f64 = v361 - v363;
        let v365: f64 = v357 + v364;
        let v366: f64 = v287 * v365;
        let v367: f64 = v343 - v366;
        let v368: f64 = v282 + v367;
        let v369: f64 = v220 * v368;
        let v370: f64 = v238 * v231;
        let v371: f64 = v251 * v235;
        let v372: f64 = v370 - v371;
        let v373: f64 = v254 * v246;
        let v374: f64 = v372 + v373;
        let v375: f64 = v244 * v263;
        let v376: f64 = v221 * v244;
        let v377: f64 = v233 * v249;
        let v378: f64 = v376 - v377;
        let v379: f64 = v238 * v228;
        let v380: f64 = v378 + v379;
        let v381: f64 = v249 * v380;
        let v382: f64 = v375 + v381;
        let v383: f64 = v374 + v382;
        let v384: f64 = params[41];
        let v385: f64 = v384 * v208;
        (
            v200,
            v208,
            v210,
            v215,
            v218,
            v220,
            v223,
            v228,
            v231,
            v233,
            v235,
            v244,
            v246,
            v249,
            v251,
            v256,
            v259,
            v267,
            v275,
            v277,
            v279,
            v284,
            v287,
            v292,
            v295,
            v303,
            v305,
            v308,
            v310,
            v314,
            v317,
            v318,
            v327,
            v331,
            v333,
            v336,
            v339,
            v342,
            v353,
            v360,
            v362,
            v365,
            v368,
            v369,
            v380,
            v383,
            v384,
            v385,
        )
    };
    let (
        v401,
        v402,
        v406,
        v409,
        v418,
        v471,
        v473,
        v485,
        v509,
        v517,
        v538,
        v558,
        v561,
        v563,
        v566,
        v567,
        v568,
        v570,
        v572,
        v575,
        v576,
        v577,
        v578,
    ) = {
        let v386: f64 = v267 * v336;
        let v387: f64 = v385 + v386;
        let v388: f64 = v383 - v387;
        let v389: f64 = v308 * v295;
        let v390: f64 = v314 * v305;
        let v391: f64 = v389 - v390;
        let v392: f64 = v317 * v310;
        let v393: f64 = v391 + v392;
        let v394: f64 = v303 * v327;
        let v395: f64 = v292 * v353;
        let v396: f64 = v394 + v395;
        let v397: f64 = v393 + v396;
        let v398: f64 = v362 * v339;
        let v399: f64 = v331 * v360;
        let v400: f64 = v398 + v399;
        let v401: f64 = v397 - v400;
        let v402: f64 = v388 + v401;
        let v403: f64 = v223 * v402;
        let v404: f64 = v369 - v403;
        let v405: f64 = v218 + v404;
        let v406: f64 = params[30];
        let v407: f64 = v406 * v208;
        let v408: f64 = v155 * v191;
        let v409: f64 = params[31];
        let v410: f64 = v159 * v409;
        let v411: f64 = v408 - v410;
        let v412: f64 = v152 * v409;
        let v413: f64 = v168 * v210;
        let v414: f64 = v412 - v413;
        let v415: f64 = v168 * v414;
        let v416: f64 = v173 * v210;
        let v417: f64 = v152 * v191;
        let v418: f64 = v416 - v417;
        let v419: f64 = v173 * v418;
        let v420: f64 = v415 - v419;
        let v421: f64 = v411 + v420;
        let v422: f64 = v407 + v421;
        let v423: f64 = v246 * v384;
        let v424: f64 = v231 * v279;
        let v425: f64 = v423 - v424;
        let v426: f64 = v249 * v279;
        let v427: f64 = v228 * v267;
        let v428: f64 = v426 + v427;
        let v429: f64 = v228 * v428;
        let v430: f64 = v244 * v267;
        let v431: f64 = v249 * v384;
        let v432: f64 = v430 + v431;
        let v433: f64 = v244 * v432;
        let v434: f64 = v429 + v433;
        let v435: f64 = v425 - v434;
        let v436: f64 = params[40];
        let v437: f64 = v436 * v208;
        let v438: f64 = v435 - v437;
        let v439: f64 = params[50];
        let v440: f64 = v439 * v360;
        let v441: f64 = v305 * v333;
        let v442: f64 = v310 * v331;
        let v443: f64 = v441 + v442;
        let v444: f64 = v303 * v331;
        let v445: f64 = v292 * v362;
        let v446: f64 = v444 + v445;
        let v447: f64 = v292 * v446;
        let v448: f64 = v318 * v362;
        let v449: f64 = v303 * v333;
        let v450: f64 = v448 - v449;
        let v451: f64 = v318 * v450;
        let v452: f64 = v447 + v451;
        let v453: f64 = v443 + v452;
        let v454: f64 = v440 - v453;
        let v455: f64 = v287 * v454;
        let v456: f64 = v310 * v362;
        let v457: f64 = v295 * v333;
        let v458: f64 = v456 - v457;
        let v459: f64 = v292 * v333;
        let v460: f64 = v318 * v331;
        let v461: f64 = v459 + v460;
        let v462: f64 = v318 * v461;
        let v463: f64 = v303 * v446;
        let v464: f64 = v462 + v463;
        let v465: f64 = v458 - v464;
        let v466: f64 = v439 * v339;
        let v467: f64 = v465 - v466;
        let v468: f64 = v284 * v467;
        let v469: f64 = v455 + v468;
        let v470: f64 = v438 + v469;
        let v471: f64 = v422 - v470;
        let v472: f64 = v43 * v471;
        let v473: f64 = v405 + v472;
        let v474: f64 = v144 * v473;
        let v475: f64 = v162 * v155;
        let v476: f64 = v175 * v159;
        let v477: f64 = v475 + v476;
        let v478: f64 = v178 * v170;
        let v479: f64 = v477 + v478;
        let v480: f64 = v168 * v187;
        let v481: f64 = v145 * v168;
        let v482: f64 = v157 * v173;
        let v483: f64 = v481 + v482;
        let v484: f64 = v162 * v152;
        let v485: f64 = v483 + v484;
        let v486: f64 = v173 * v485;
        let v487: f64 = v480 - v486;
        let v488: f64 = v479 + v487;
        let v489: f64 = v409 * v215;
        let v490: f64 = v191 * v275;
        let v491: f64 = v489 - v490;
        let v492: f64 = v488 + v491;
        let v493: f64 = v233 * v231;
        let v494: f64 = v259 * v235;
        let v495: f64 = v493 - v494;
        let v496: f64 = v251 * v246;
        let v497: f64 = v495 + v496;
        let v498: f64 = v228 * v380;
        let v499: f64 = v244 * v256;
        let v500: f64 = v498 - v499;
        let v501: f64 = v497 + v500;
        let v502: f64 = v279 * v336;
        let v503: f64 = v384 * v277;
        let v504: f64 = v502 - v503;
        let v505: f64 = v501 + v504;
        let v506: f64 = v287 * v342;
        let v507: f64 = v284 * v365;
        let v508: f64 = v506 + v507;
        let v509: f64 = v505 + v508;
        let v510: f64 = v492 - v509;
        let v511: f64 = v406 * v275;
        let v512: f64 = v159 * v210;
        let v513: f64 = v170 * v191;
        let v514: f64 = v512 - v513;
        let v515: f64 = v168 * v191;
        let v516: f64 = v173 * v409;
        let v517: f64 = v515 - v516;
        let v518: f64 = v173 * v517;
        let v519: f64 = v152 * v414;
        let v520: f64 = v518 - v519;
        let v521: f64 = v514 + v520;
        let v522: f64 = v511 + v521;
        let v523: f64 = v436 * v336;
        let v524: f64 = v235 * v279;
        let v525: f64 = v246 * v267;
        let v526: f64 = v524 + v525;
        let v527: f64 = v249 * v432;
        let v528: f64 = v228 * v384;
        let v529: f64 = v244 * v279;
        let v530: f64 = v528 - v529;
        let v531: f64 = v228 * v530;
        let v532: f64 = v527 + v531;
        let v533: f64 = v526 + v532;
        let v534: f64 = v523 - v533;
        let v535: f64 = v284 * v454;
        let v536: f64 = v287 * v467;
        let v537: f64 = v535 - v536;
        let v538: f64 = v534 + v537;
        let v539: f64 = v220 * v538;
        let v540: f64 = v436 * v277;
        let v541: f64 = v231 * v267;
        let v542: f64 = v235 * v384;
        let v543: f64 = v541 + v542;
        let v544: f64 = v244 * v530;
        let v545: f64 = v249 * v428;
        let v546: f64 = v544 - v545;
        let v547: f64 = v543 + v546;
        let v548: f64 = v540 + v547;
        let v549: f64 = v439 * v277;
        let v550: f64 = v295 * v331;
        let v551: f64 = v305 * v362;
        let v552: f64 = v550 + v551;
        let v553: f64 = v303 * v450;
        let v554: f64 = v292 * v461;
        let v555: f64 = v553 - v554;
        let v556: f64 = v552 + v555;
        let v557: f64 = v549 + v556;
        let v558: f64 = v548 + v557;
        let v559: f64 = v223 * v558;
        let v560: f64 = v539 - v559;
        let v561: f64 = v522 + v560;
        let v562: f64 = v43 * v561;
        let v563: f64 = v510 - v562;
        let v564: f64 = v147 * v563;
        let v565: f64 = v474 + v564;
        let v566: f64 = v142 + v565;
        let v567: f64 = params[20];
        let v568: f64 = v567 * v128;
        let v569: f64 = v72 * v108;
        let v570: f64 = params[21];
        let v571: f64 = v76 * v570;
        let v572: f64 = v569 + v571;
        let v573: f64 = v69 * v570;
        let v574: f64 = v85 * v130;
        let v575: f64 = v573 - v574;
        let v576: f64 = v85 * v575;
        let v577: f64 = v90 * v130;
        let v578: f64 = v69 * v108;
        (
            v401,
            v402,
            v406,
            v409,
            v418,
            v471,
            v473,
            v485,
            v509,
            v517,
            v538,
            v558,
            v561,
            v563,
            v566,
            v567,
            v568,
            v570,
            v572,
            v575,
            v576,
            v577,
            v578,
        )
    };
    let (v635, v718, v769, v770, v771) = {
        let v579: f64 = v577 + v578;
        let v580: f64 = v90 * v579;
        let v581: f64 = v576 - v580;
        let v582: f64 = v572 + v581;
        let v583: f64 = v568 + v582;
        let v584: f64 = v406 * v215;
        let v585: f64 = v170 * v409;
        let v586: f64 = v155 * v210;
        let v587: f64 = v585 - v586;
        let v588: f64 = v152 * v418;
        let v589: f64 = v168 * v517;
        let v590: f64 = v588 - v589;
        let v591: f64 = v587 + v590;
        let v592: f64 = v584 + v591;
        let v593: f64 = v223 * v538;
        let v594: f64 = v220 * v558;
        let v595: f64 = v593 + v594;
        let v596: f64 = v592 + v595;
        let v597: f64 = v583 + v596;
        let v598: f64 = v117 * v597;
        let v599: f64 = v566 + v598;
        let v600: f64 = v61 * v599;
        let v601: f64 = v79 * v72;
        let v602: f64 = v92 * v76;
        let v603: f64 = v601 - v602;
        let v604: f64 = v95 * v87;
        let v605: f64 = v603 + v604;
        let v606: f64 = v85 * v104;
        let v607: f64 = v62 * v85;
        let v608: f64 = v74 * v90;
        let v609: f64 = v607 - v608;
        let v610: f64 = v79 * v69;
        let v611: f64 = v609 + v610;
        let v612: f64 = v90 * v611;
        let v613: f64 = v606 + v612;
        let v614: f64 = v605 + v613;
        let v615: f64 = v570 * v139;
        let v616: f64 = v108 * v200;
        let v617: f64 = v615 - v616;
        let v618: f64 = v614 + v617;
        let v619: f64 = v157 * v155;
        let v620: f64 = v183 * v159;
        let v621: f64 = v619 + v620;
        let v622: f64 = v175 * v170;
        let v623: f64 = v621 + v622;
        let v624: f64 = v152 * v485;
        let v625: f64 = v168 * v180;
        let v626: f64 = v624 - v625;
        let v627: f64 = v623 + v626;
        let v628: f64 = v210 * v275;
        let v629: f64 = v409 * v208;
        let v630: f64 = v628 - v629;
        let v631: f64 = v627 + v630;
        let v632: f64 = v223 * v368;
        let v633: f64 = v220 * v402;
        let v634: f64 = v632 + v633;
        let v635: f64 = v631 + v634;
        let v636: f64 = v618 + v635;
        let v637: f64 = v567 * v139;
        let v638: f64 = v87 * v570;
        let v639: f64 = v72 * v130;
        let v640: f64 = v638 - v639;
        let v641: f64 = v69 * v579;
        let v642: f64 = v85 * v108;
        let v643: f64 = v90 * v570;
        let v644: f64 = v642 + v643;
        let v645: f64 = v85 * v644;
        let v646: f64 = v641 + v645;
        let v647: f64 = v640 - v646;
        let v648: f64 = v637 + v647;
        let v649: f64 = v147 * v561;
        let v650: f64 = v144 * v471;
        let v651: f64 = v649 - v650;
        let v652: f64 = v648 + v651;
        let v653: f64 = v119 * v652;
        let v654: f64 = v567 * v200;
        let v655: f64 = v76 * v130;
        let v656: f64 = v87 * v108;
        let v657: f64 = v655 + v656;
        let v658: f64 = v90 * v644;
        let v659: f64 = v69 * v575;
        let v660: f64 = v658 + v659;
        let v661: f64 = v657 + v660;
        let v662: f64 = v654 - v661;
        let v663: f64 = v144 * v561;
        let v664: f64 = v147 * v471;
        let v665: f64 = v663 + v664;
        let v666: f64 = v662 + v665;
        let v667: f64 = v117 * v666;
        let v668: f64 = v653 - v667;
        let v669: f64 = v636 + v668;
        let v670: f64 = v64 * v669;
        let v671: f64 = v600 - v670;
        let v672: f64 = v59 + v671;
        let v673: f64 = v4 * v672;
        let v674: f64 = v14 * v12;
        let v675: f64 = v34 * v18;
        let v676: f64 = v674 + v675;
        let v677: f64 = v26 * v22;
        let v678: f64 = v676 + v677;
        let v679: f64 = v5 * v16;
        let v680: f64 = v14 * v9;
        let v681: f64 = v679 + v680;
        let v682: f64 = v21 * v10;
        let v683: f64 = v681 + v682;
        let v684: f64 = v10 * v683;
        let v685: f64 = v16 * v31;
        let v686: f64 = v684 - v685;
        let v687: f64 = v678 + v686;
        let v688: f64 = v49 * v114;
        let v689: f64 = params[11];
        let v690: f64 = v689 * v47;
        let v691: f64 = v688 - v690;
        let v692: f64 = v687 + v691;
        let v693: f64 = v64 * v599;
        let v694: f64 = v61 * v669;
        let v695: f64 = v693 + v694;
        let v696: f64 = v692 + v695;
        let v697: f64 = params[10];
        let v698: f64 = v697 * v47;
        let v699: f64 = v12 * v42;
        let v700: f64 = v18 * v689;
        let v701: f64 = v699 - v700;
        let v702: f64 = v10 * v689;
        let v703: f64 = v16 * v49;
        let v704: f64 = v702 - v703;
        let v705: f64 = v16 * v704;
        let v706: f64 = v9 * v49;
        let v707: f64 = v10 * v42;
        let v708: f64 = v706 - v707;
        let v709: f64 = v9 * v708;
        let v710: f64 = v705 - v709;
        let v711: f64 = v701 + v710;
        let v712: f64 = v698 + v711;
        let v713: f64 = v712 - v652;
        let v714: f64 = v43 * v713;
        let v715: f64 = v696 - v714;
        let v716: f64 = v7 * v715;
        let v717: f64 = v673 + v716;
        let v718: f64 = v2 + v717;
        let v719: f64 = v21 * v12;
        let v720: f64 = v26 * v18;
        let v721: f64 = v719 + v720;
        let v722: f64 = v29 * v22;
        let v723: f64 = v721 + v722;
        let v724: f64 = v16 * v38;
        let v725: f64 = v9 * v683;
        let v726: f64 = v724 - v725;
        let v727: f64 = v723 + v726;
        let v728: f64 = v689 * v56;
        let v729: f64 = v42 * v114;
        let v730: f64 = v728 - v729;
        let v731: f64 = v727 + v730;
        let v732: f64 = v74 * v72;
        let v733: f64 = v100 * v76;
        let v734: f64 = v732 - v733;
        let v735: f64 = v92 * v87;
        let v736: f64 = v734 + v735;
        let v737: f64 = v69 * v611;
        let v738: f64 = v85 * v97;
        let v739: f64 = v737 - v738;
        let v740: f64 = v736 + v739;
        let v741: f64 = v130 * v200;
        let v742: f64 = v570 * v128;
        let v743: f64 = v741 - v742;
        let v744: f64 = v740 + v743;
        let v745: f64 = v147 * v473;
        let v746: f64 = v144 * v563;
        let v747: f64 = v745 - v746;
        let v748: f64 = v744 + v747;
        let v749: f64 = v119 * v597;
        let v750: f64 = v748 - v749;
        let v751: f64 = v731 - v750;
        let v752: f64 = v697 * v56;
        let v753: f64 = v22 * v689;
        let v754: f64 = v12 * v49;
        let v755: f64 = v753 - v754;
        let v756: f64 = v10 * v708;
        let v757: f64 = v16 * v42;
        let v758: f64 = v9 * v689;
        let v759: f64 = v757 - v758;
        let v760: f64 = v16 * v759;
        let v761: f64 = v756 - v760;
        let v762: f64 = v755 + v761;
        let v763: f64 = v752 + v762;
        let v764: f64 = v64 * v666;
        let v765: f64 = v61 * v597;
        let v766: f64 = v764 + v765;
        let v767: f64 = v763 + v766;
        let v768: f64 = v43 * v767;
        let v769: f64 = v751 + v768;
        let v770: f64 = -v750;
        let v771: f64 = -v509;
        (v635, v718, v769, v770, v771)
    };
    [v718, v769, v770, v635, v771, v401]
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
/// Operation count: 1307 floating-point operations, 10 trig calls.
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
        v17,
        v20,
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
        v85,
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
        v136,
        v138,
        v141,
        v145,
        v147,
        v150,
        v152,
        v155,
        v157,
        v160,
        v164,
        v168,
        v177,
        v185,
        v187,
        v189,
        v192,
        v195,
        v197,
        v198,
        v200,
    ) = {
        let v0: f64 = tau[0];
        let v1: f64 = q[1];
        let (v2, v4): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = params[14];
        let v5: f64 = qd[0];
        let v6: f64 = v4 * v5;
        let v7: f64 = qd[1];
        let v8: f64 = v6 * v7;
        let v9: f64 = v3 * v8;
        let v10: f64 = params[15];
        let v11: f64 = v2 * v5;
        let v12: f64 = v11 * v7;
        let v13: f64 = v10 * v12;
        let v14: f64 = v9 - v13;
        let v15: f64 = params[16];
        let v16: f64 = v15 * v11;
        let v17: f64 = params[18];
        let v18: f64 = v17 * v6;
        let v19: f64 = v16 + v18;
        let v20: f64 = params[19];
        let v21: f64 = v20 * v7;
        let v22: f64 = v19 + v21;
        let v23: f64 = v6 * v22;
        let v24: f64 = v10 * v11;
        let v25: f64 = params[17];
        let v26: f64 = v25 * v6;
        let v27: f64 = v24 + v26;
        let v28: f64 = v17 * v7;
        let v29: f64 = v27 + v28;
        let v30: f64 = v7 * v29;
        let v31: f64 = v23 - v30;
        let v32: f64 = v14 + v31;
        let v33: f64 = params[12];
        let v34: f64 = 0.4318_f64;
        let v35: f64 = v34 * v12;
        let v36: f64 = v34 * v7;
        let v37: f64 = v11 * v36;
        let v38: f64 = v35 + v37;
        let v39: f64 = v33 * v38;
        let v40: f64 = params[13];
        let v41: f64 = 9.81_f64;
        let v42: f64 = v41 * v4;
        let v43: f64 = v34 * v6;
        let v44: f64 = v11 * v43;
        let v45: f64 = v42 + v44;
        let v46: f64 = v40 * v45;
        let v47: f64 = v39 - v46;
        let v48: f64 = v32 + v47;
        let v49: f64 = q[2];
        let (v53, v50): (f64, f64) = ::armdyn_runtime::libm::sincos(v49);
        let v51: f64 = params[24];
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
        let v63: f64 = params[26];
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
        let v76: f64 = params[28];
        let v77: f64 = v76 * v74;
        let v78: f64 = v75 - v77;
        let v79: f64 = params[29];
        let v80: f64 = v79 * v58;
        let v81: f64 = v78 + v80;
        let v82: f64 = v74 * v81;
        let v83: f64 = params[25];
        let v84: f64 = v83 * v69;
        let v85: f64 = params[27];
        let v86: f64 = v85 * v74;
        let v87: f64 = v84 - v86;
        let v88: f64 = v76 * v58;
        let v89: f64 = v87 + v88;
        let v90: f64 = v58 * v89;
        let v91: f64 = v82 + v90;
        let v92: f64 = v73 - v91;
        let v93: f64 = params[22];
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
        let v113: f64 = params[23];
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
        let (v130, v127): (f64, f64) = ::armdyn_runtime::libm::sincos(v126);
        let v128: f64 = params[34];
        let v129: f64 = v127 * v61;
        let v131: f64 = v130 * v69;
        let v132: f64 = v127 * v74;
        let v133: f64 = v131 + v132;
        let v134: f64 = qd[3];
        let v135: f64 = v133 * v134;
        let v136: f64 = v129 - v135;
        let v137: f64 = v128 * v136;
        let v138: f64 = params[35];
        let v139: f64 = v138 * v71;
        let v140: f64 = v137 - v139;
        let v141: f64 = params[36];
        let v142: f64 = v130 * v61;
        let v143: f64 = v127 * v69;
        let v144: f64 = v130 * v74;
        let v145: f64 = v143 - v144;
        let v146: f64 = v145 * v134;
        let v147: f64 = v142 + v146;
        let v148: f64 = v141 * v147;
        let v149: f64 = v140 + v148;
        let v150: f64 = v58 + v134;
        let v151: f64 = v141 * v145;
        let v152: f64 = params[38];
        let v153: f64 = v152 * v150;
        let v154: f64 = v151 + v153;
        let v155: f64 = params[39];
        let v156: f64 = v155 * v133;
        let v157: f64 = v154 + v156;
        let v158: f64 = v150 * v157;
        let v159: f64 = v138 * v145;
        let v160: f64 = params[37];
        let v161: f64 = v160 * v150;
        let v162: f64 = v159 + v161;
        let v163: f64 = v152 * v133;
        let v164: f64 = v162 + v163;
        let v165: f64 = v133 * v164;
        let v166: f64 = v158 - v165;
        let v167: f64 = v149 + v166;
        let v168: f64 = params[32];
        let v169: f64 = v50 * v99;
        let v170: f64 = v53 * v45;
        let v171: f64 = v169 + v170;
        let v172: f64 = v102 * v71;
        let v173: f64 = v74 * v118;
        let v174: f64 = v58 * v105;
        let v175: f64 = v173 + v174;
        let v176: f64 = v172 - v175;
        let v177: f64 = v171 + v176;
        let v178: f64 = v130 * v177;
        let v179: f64 = v127 * v122;
        let v180: f64 = v178 + v179;
        let v181: f64 = v34 * v136;
        let v182: f64 = v34 * v133;
        let v183: f64 = v150 * v182;
        let v184: f64 = v181 + v183;
        let v185: f64 = v180 + v184;
        let v186: f64 = v168 * v185;
        let v187: f64 = params[33];
        let v188: f64 = v133 * v182;
        let v189: f64 = v34 * v145;
        let v190: f64 = v145 * v189;
        let v191: f64 = v188 + v190;
        let v192: f64 = v111 - v191;
        let v193: f64 = v187 * v192;
        let v194: f64 = v186 - v193;
        let v195: f64 = v167 + v194;
        let v196: f64 = q[4];
        let (v200, v197): (f64, f64) = ::armdyn_runtime::libm::sincos(v196);
        let v198: f64 = params[44];
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
            v20,
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
            v85,
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
            v136,
            v138,
            v141,
            v145,
            v147,
            v150,
            v152,
            v155,
            v157,
            v160,
            v164,
            v168,
            v177,
            v185,
            v187,
            v189,
            v192,
            v195,
            v197,
            v198,
            v200,
        )
    };
    let (
        v205,
        v208,
        v210,
        v213,
        v219,
        v221,
        v224,
        v226,
        v229,
        v231,
        v234,
        v242,
        v250,
        v252,
        v254,
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
        v296,
        v304,
        v306,
        v309,
        v312,
        v315,
        v335,
        v338,
        v341,
        v353,
        v357,
        v374,
        v375,
        v378,
        v379,
        v382,
        v387,
        v391,
        v395,
        v396,
        v397,
    ) = {
        let v199: f64 = v197 * v136;
        let v201: f64 = v200 * v71;
        let v202: f64 = v199 - v201;
        let v203: f64 = v197 * v150;
        let v204: f64 = v200 * v145;
        let v205: f64 = v203 - v204;
        let v206: f64 = qd[4];
        let v207: f64 = v205 * v206;
        let v208: f64 = v202 + v207;
        let v209: f64 = v198 * v208;
        let v210: f64 = params[45];
        let v211: f64 = v210 * v147;
        let v212: f64 = v209 - v211;
        let v213: f64 = params[46];
        let v214: f64 = v200 * v136;
        let v215: f64 = v197 * v71;
        let v216: f64 = v214 + v215;
        let v217: f64 = v197 * v145;
        let v218: f64 = v200 * v150;
        let v219: f64 = v217 + v218;
        let v220: f64 = v219 * v206;
        let v221: f64 = v216 + v220;
        let v222: f64 = v213 * v221;
        let v223: f64 = v212 - v222;
        let v224: f64 = v133 + v206;
        let v225: f64 = v213 * v219;
        let v226: f64 = params[48];
        let v227: f64 = v226 * v224;
        let v228: f64 = v225 - v227;
        let v229: f64 = params[49];
        let v230: f64 = v229 * v205;
        let v231: f64 = v228 + v230;
        let v232: f64 = v224 * v231;
        let v233: f64 = v210 * v219;
        let v234: f64 = params[47];
        let v235: f64 = v234 * v224;
        let v236: f64 = v233 - v235;
        let v237: f64 = v226 * v205;
        let v238: f64 = v236 + v237;
        let v239: f64 = v205 * v238;
        let v240: f64 = v232 + v239;
        let v241: f64 = v223 - v240;
        let v242: f64 = params[42];
        let v243: f64 = v197 * v192;
        let v244: f64 = v127 * v177;
        let v245: f64 = v130 * v122;
        let v246: f64 = v244 - v245;
        let v247: f64 = v150 * v189;
        let v248: f64 = v34 * v147;
        let v249: f64 = v247 - v248;
        let v250: f64 = v246 + v249;
        let v251: f64 = v200 * v250;
        let v252: f64 = v243 - v251;
        let v253: f64 = v242 * v252;
        let v254: f64 = params[43];
        let v255: f64 = v254 * v185;
        let v256: f64 = v253 + v255;
        let v257: f64 = v241 + v256;
        let v258: f64 = q[5];
        let (v262, v259): (f64, f64) = ::armdyn_runtime::libm::sincos(v258);
        let v260: f64 = params[54];
        let v261: f64 = v259 * v208;
        let v263: f64 = v262 * v147;
        let v264: f64 = v261 - v263;
        let v265: f64 = v262 * v219;
        let v266: f64 = v259 * v224;
        let v267: f64 = v265 + v266;
        let v268: f64 = qd[5];
        let v269: f64 = v267 * v268;
        let v270: f64 = v264 - v269;
        let v271: f64 = v260 * v270;
        let v272: f64 = params[55];
        let v273: f64 = v262 * v208;
        let v274: f64 = v259 * v147;
        let v275: f64 = v273 + v274;
        let v276: f64 = v259 * v219;
        let v277: f64 = v262 * v224;
        let v278: f64 = v276 - v277;
        let v279: f64 = v278 * v268;
        let v280: f64 = v275 + v279;
        let v281: f64 = v272 * v280;
        let v282: f64 = v271 - v281;
        let v283: f64 = params[56];
        let v284: f64 = v283 * v221;
        let v285: f64 = v282 - v284;
        let v286: f64 = v283 * v278;
        let v287: f64 = params[58];
        let v288: f64 = v287 * v267;
        let v289: f64 = v286 - v288;
        let v290: f64 = params[59];
        let v291: f64 = v205 + v268;
        let v292: f64 = v290 * v291;
        let v293: f64 = v289 + v292;
        let v294: f64 = v267 * v293;
        let v295: f64 = v272 * v278;
        let v296: f64 = params[57];
        let v297: f64 = v296 * v267;
        let v298: f64 = v295 - v297;
        let v299: f64 = v287 * v291;
        let v300: f64 = v298 + v299;
        let v301: f64 = v291 * v300;
        let v302: f64 = v294 + v301;
        let v303: f64 = v285 - v302;
        let v304: f64 = params[52];
        let v305: f64 = v304 * v252;
        let v306: f64 = params[53];
        let v307: f64 = v197 * v250;
        let v308: f64 = v200 * v192;
        let v309: f64 = v307 + v308;
        let v310: f64 = v262 * v309;
        let v311: f64 = v259 * v185;
        let v312: f64 = v310 + v311;
        let v313: f64 = v306 * v312;
        let v314: f64 = v305 + v313;
        let v315: f64 = v303 + v314;
        let v316: f64 = v259 * v315;
        let v317: f64 = v272 * v270;
        let v318: f64 = v296 * v280;
        let v319: f64 = v317 - v318;
        let v320: f64 = v287 * v221;
        let v321: f64 = v319 - v320;
        let v322: f64 = v260 * v278;
        let v323: f64 = v272 * v267;
        let v324: f64 = v322 - v323;
        let v325: f64 = v283 * v291;
        let v326: f64 = v324 + v325;
        let v327: f64 = v291 * v326;
        let v328: f64 = v278 * v293;
        let v329: f64 = v327 - v328;
        let v330: f64 = v321 + v329;
        let v331: f64 = v259 * v309;
        let v332: f64 = v262 * v185;
        let v333: f64 = v331 - v332;
        let v334: f64 = v306 * v333;
        let v335: f64 = params[51];
        let v336: f64 = v335 * v252;
        let v337: f64 = v334 - v336;
        let v338: f64 = v330 + v337;
        let v339: f64 = v262 * v338;
        let v340: f64 = v316 - v339;
        let v341: f64 = v257 + v340;
        let v342: f64 = v197 * v341;
        let v343: f64 = v213 * v208;
        let v344: f64 = v226 * v147;
        let v345: f64 = v343 - v344;
        let v346: f64 = v229 * v221;
        let v347: f64 = v345 - v346;
        let v348: f64 = v219 * v238;
        let v349: f64 = v198 * v219;
        let v350: f64 = v210 * v224;
        let v351: f64 = v349 - v350;
        let v352: f64 = v213 * v205;
        let v353: f64 = v351 + v352;
        let v354: f64 = v224 * v353;
        let v355: f64 = v348 + v354;
        let v356: f64 = v347 + v355;
        let v357: f64 = params[41];
        let v358: f64 = v357 * v185;
        let v359: f64 = v242 * v309;
        let v360: f64 = v358 + v359;
        let v361: f64 = v356 - v360;
        let v362: f64 = v283 * v270;
        let v363: f64 = v287 * v280;
        let v364: f64 = v362 - v363;
        let v365: f64 = v290 * v221;
        let v366: f64 = v364 - v365;
        let v367: f64 = v278 * v300;
        let v368: f64 = v267 * v326;
        let v369: f64 = v367 + v368;
        let v370: f64 = v366 + v369;
        let v371: f64 = v335 * v312;
        let v372: f64 = v304 * v333;
        let v373: f64 = v371 + v372;
        let v374: f64 = v370 - v373;
        let v375: f64 = v361 + v374;
        let v376: f64 = v200 * v375;
        let v377: f64 = v342 - v376;
        let v378: f64 = v195 + v377;
        let v379: f64 = params[30];
        let v380: f64 = v379 * v185;
        let v381: f64 = v136 * v168;
        let v382: f64 = params[31];
        let v383: f64 = v71 * v382;
        let v384: f64 = v381 + v383;
        let v385: f64 = v133 * v382;
        let v386: f64 = v145 * v187;
        let v387: f64 = v385 - v386;
        let v388: f64 = v145 * v387;
        let v389: f64 = v150 * v187;
        let v390: f64 = v133 * v168;
        let v391: f64 = v389 - v390;
        let v392: f64 = v150 * v391;
        let v393: f64 = v388 - v392;
        let v394: f64 = v384 + v393;
        let v395: f64 = v380 + v394;
        let v396: f64 = params[50];
        let v397: f64 = v396 * v333;
        (
            v205,
            v208,
            v210,
            v213,
            v219,
            v221,
            v224,
            v226,
            v229,
            v231,
            v234,
            v242,
            v250,
            v252,
            v254,
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
            v296,
            v304,
            v306,
            v309,
            v312,
            v315,
            v335,
            v338,
            v341,
            v353,
            v357,
            v374,
            v375,
            v378,
            v379,
            v382,
            v387,
            v391,
            v395,
            v396,
            v397,
        )
    };
    let (
        v427,
        v444,
        v446,
        v482,
        v534,
        v536,
        v540,
        v543,
        v546,
        v550,
        v568,
        v570,
        v571,
        v580,
        v587,
        v596,
    ) = {
        let v398: f64 = v221 * v304;
        let v399: f64 = v280 * v306;
        let v400: f64 = v398 - v399;
        let v401: f64 = v278 * v304;
        let v402: f64 = v267 * v335;
        let v403: f64 = v401 + v402;
        let v404: f64 = v267 * v403;
        let v405: f64 = v291 * v335;
        let v406: f64 = v278 * v306;
        let v407: f64 = v405 - v406;
        let v408: f64 = v291 * v407;
        let v409: f64 = v404 + v408;
        let v410: f64 = v400 - v409;
        let v411: f64 = v397 + v410;
        let v412: f64 = v262 * v411;
        let v413: f64 = v396 * v312;
        let v414: f64 = v221 * v335;
        let v415: f64 = v270 * v306;
        let v416: f64 = v414 + v415;
        let v417: f64 = v267 * v306;
        let v418: f64 = v291 * v304;
        let v419: f64 = v417 + v418;
        let v420: f64 = v291 * v419;
        let v421: f64 = v278 * v403;
        let v422: f64 = v420 + v421;
        let v423: f64 = v416 + v422;
        let v424: f64 = v413 + v423;
        let v425: f64 = v259 * v424;
        let v426: f64 = v412 - v425;
        let v427: f64 = params[40];
        let v428: f64 = v427 * v185;
        let v429: f64 = v221 * v357;
        let v430: f64 = v208 * v254;
        let v431: f64 = v429 + v430;
        let v432: f64 = v224 * v254;
        let v433: f64 = v205 * v242;
        let v434: f64 = v432 + v433;
        let v435: f64 = v205 * v434;
        let v436: f64 = v219 * v242;
        let v437: f64 = v224 * v357;
        let v438: f64 = v436 + v437;
        let v439: f64 = v219 * v438;
        let v440: f64 = v435 + v439;
        let v441: f64 = v431 + v440;
        let v442: f64 = v428 + v441;
        let v443: f64 = v426 - v442;
        let v444: f64 = v395 - v443;
        let v445: f64 = v34 * v444;
        let v446: f64 = v378 + v445;
        let v447: f64 = v127 * v446;
        let v448: f64 = v141 * v136;
        let v449: f64 = v152 * v71;
        let v450: f64 = v448 - v449;
        let v451: f64 = v155 * v147;
        let v452: f64 = v450 + v451;
        let v453: f64 = v145 * v164;
        let v454: f64 = v128 * v145;
        let v455: f64 = v138 * v150;
        let v456: f64 = v454 + v455;
        let v457: f64 = v141 * v133;
        let v458: f64 = v456 + v457;
        let v459: f64 = v150 * v458;
        let v460: f64 = v453 - v459;
        let v461: f64 = v452 + v460;
        let v462: f64 = v382 * v192;
        let v463: f64 = v168 * v250;
        let v464: f64 = v462 - v463;
        let v465: f64 = v461 + v464;
        let v466: f64 = v210 * v208;
        let v467: f64 = v234 * v147;
        let v468: f64 = v466 - v467;
        let v469: f64 = v226 * v221;
        let v470: f64 = v468 - v469;
        let v471: f64 = v205 * v353;
        let v472: f64 = v219 * v231;
        let v473: f64 = v471 - v472;
        let v474: f64 = v470 + v473;
        let v475: f64 = v254 * v309;
        let v476: f64 = v357 * v252;
        let v477: f64 = v475 - v476;
        let v478: f64 = v474 + v477;
        let v479: f64 = v262 * v315;
        let v480: f64 = v259 * v338;
        let v481: f64 = v479 + v480;
        let v482: f64 = v478 + v481;
        let v483: f64 = v465 - v482;
        let v484: f64 = v379 * v250;
        let v485: f64 = v145 * v168;
        let v486: f64 = v150 * v382;
        let v487: f64 = v485 - v486;
        let v488: f64 = v150 * v487;
        let v489: f64 = v133 * v387;
        let v490: f64 = v488 - v489;
        let v491: f64 = v71 * v187;
        let v492: f64 = v147 * v168;
        let v493: f64 = v491 + v492;
        let v494: f64 = v490 - v493;
        let v495: f64 = v484 + v494;
        let v496: f64 = v427 * v309;
        let v497: f64 = v221 * v242;
        let v498: f64 = v147 * v254;
        let v499: f64 = v497 - v498;
        let v500: f64 = v224 * v438;
        let v501: f64 = v205 * v357;
        let v502: f64 = v219 * v254;
        let v503: f64 = v501 - v502;
        let v504: f64 = v205 * v503;
        let v505: f64 = v500 + v504;
        let v506: f64 = v499 - v505;
        let v507: f64 = v496 + v506;
        let v508: f64 = v259 * v411;
        let v509: f64 = v262 * v424;
        let v510: f64 = v508 + v509;
        let v511: f64 = v507 + v510;
        let v512: f64 = v197 * v511;
        let v513: f64 = v427 * v252;
        let v514: f64 = v208 * v242;
        let v515: f64 = v147 * v357;
        let v516: f64 = v514 + v515;
        let v517: f64 = v219 * v503;
        let v518: f64 = v224 * v434;
        let v519: f64 = v517 - v518;
        let v520: f64 = v516 + v519;
        let v521: f64 = v513 + v520;
        let v522: f64 = v396 * v252;
        let v523: f64 = v270 * v304;
        let v524: f64 = v280 * v335;
        let v525: f64 = v523 + v524;
        let v526: f64 = v278 * v407;
        let v527: f64 = v267 * v419;
        let v528: f64 = v526 - v527;
        let v529: f64 = v525 + v528;
        let v530: f64 = v522 + v529;
        let v531: f64 = v521 + v530;
        let v532: f64 = v200 * v531;
        let v533: f64 = v512 - v532;
        let v534: f64 = v495 + v533;
        let v535: f64 = v34 * v534;
        let v536: f64 = v483 - v535;
        let v537: f64 = v130 * v536;
        let v538: f64 = v447 + v537;
        let v539: f64 = v125 + v538;
        let v540: f64 = params[20];
        let v541: f64 = v540 * v111;
        let v542: f64 = v61 * v93;
        let v543: f64 = params[21];
        let v544: f64 = v58 * v543;
        let v545: f64 = v69 * v113;
        let v546: f64 = v544 - v545;
        let v547: f64 = v69 * v546;
        let v548: f64 = v74 * v113;
        let v549: f64 = v58 * v93;
        let v550: f64 = v548 + v549;
        let v551: f64 = v74 * v550;
        let v552: f64 = v547 - v551;
        let v553: f64 = v542 + v552;
        let v554: f64 = v541 + v553;
        let v555: f64 = v379 * v192;
        let v556: f64 = v147 * v382;
        let v557: f64 = v136 * v187;
        let v558: f64 = v556 - v557;
        let v559: f64 = v133 * v391;
        let v560: f64 = v145 * v487;
        let v561: f64 = v559 - v560;
        let v562: f64 = v558 + v561;
        let v563: f64 = v555 + v562;
        let v564: f64 = v200 * v511;
        let v565: f64 = v197 * v531;
        let v566: f64 = v564 + v565;
        let v567: f64 = v563 + v566;
        let v568: f64 = v554 + v567;
        let v569: f64 = v102 * v568;
        let v570: f64 = v539 + v569;
        let v571: f64 = v50 * v570;
        let v572: f64 = v63 * v61;
        let v573: f64 = v79 * v71;
        let v574: f64 = v572 - v573;
        let v575: f64 = v69 * v89;
        let v576: f64 = v51 * v69;
        let v577: f64 = v83 * v74;
        let v578: f64 = v576 - v577;
        let v579: f64 = v63 * v58;
        let v580: f64 = v578 + v579;
        let v581: f64 = v74 * v580;
        let v582: f64 = v575 + v581;
        let v583: f64 = v574 + v582;
        let v584: f64 = v543 * v122;
        let v585: f64 = v93 * v177;
        let v586: f64 = v584 + v585;
        let v587: f64 = v583 - v586;
        let v588: f64 = v138 * v136;
        let v589: f64 = v160 * v71;
        let v590: f64 = v588 - v589;
        let v591: f64 = v152 * v147;
        let v592: f64 = v590 + v591;
        let v593: f64 = v133 * v458;
        let v594: f64 = v145 * v157;
        let v595: f64 = v593 - v594;
        let v596: f64 = v592 + v595;
        (
            v427,
            v444,
            v446,
            v482,
            v534,
            v536,
            v540,
            v543,
            v546,
            v550,
            v568,
            v570,
            v571,
            v580,
            v587,
            v596,
        )
    };
    let (
        v604,
        v633,
        v648,
        v654,
        v662,
        v673,
        v686,
        v689,
        v693,
        v700,
        v701,
        v711,
        v714,
        v717,
        v719,
        v721,
        v723,
        v733,
        v735,
        v741,
        v743,
        v744,
        v746,
        v748,
        v753,
        v756,
        v760,
        v764,
        v765,
        v768,
        v771,
        v774,
        v778,
        v780,
        v781,
        v782,
        v784,
        v788,
        v790,
        v791,
        v794,
        v795,
    ) = {
        let v597: f64 = v187 * v250;
        let v598: f64 = v382 * v185;
        let v599: f64 = v597 - v598;
        let v600: f64 = v596 + v599;
        let v601: f64 = v200 * v341;
        let v602: f64 = v197 * v375;
        let v603: f64 = v601 + v602;
        let v604: f64 = v600 + v603;
        let v605: f64 = v587 + v604;
        let v606: f64 = v130 * v534;
        let v607: f64 = v127 * v444;
        let v608: f64 = v606 - v607;
        let v609: f64 = v540 * v122;
        let v610: f64 = v71 * v543;
        let v611: f64 = v61 * v113;
        let v612: f64 = v610 + v611;
        let v613: f64 = v58 * v550;
        let v614: f64 = v69 * v93;
        let v615: f64 = v74 * v543;
        let v616: f64 = v614 + v615;
        let v617: f64 = v69 * v616;
        let v618: f64 = v613 + v617;
        let v619: f64 = v612 + v618;
        let v620: f64 = v609 + v619;
        let v621: f64 = v608 - v620;
        let v622: f64 = v104 * v621;
        let v623: f64 = v540 * v177;
        let v624: f64 = v71 * v93;
        let v625: f64 = v74 * v616;
        let v626: f64 = v58 * v546;
        let v627: f64 = v625 + v626;
        let v628: f64 = v624 - v627;
        let v629: f64 = v623 + v628;
        let v630: f64 = v127 * v534;
        let v631: f64 = v130 * v444;
        let v632: f64 = v630 + v631;
        let v633: f64 = v629 + v632;
        let v634: f64 = v102 * v633;
        let v635: f64 = v622 - v634;
        let v636: f64 = v605 + v635;
        let v637: f64 = v53 * v636;
        let v638: f64 = v571 - v637;
        let v639: f64 = v48 + v638;
        let v640: f64 = v2 * v639;
        let v641: f64 = v10 * v8;
        let v642: f64 = v25 * v12;
        let v643: f64 = v641 - v642;
        let v644: f64 = v3 * v11;
        let v645: f64 = v10 * v6;
        let v646: f64 = v644 + v645;
        let v647: f64 = v15 * v7;
        let v648: f64 = v646 + v647;
        let v649: f64 = v7 * v648;
        let v650: f64 = v11 * v22;
        let v651: f64 = v649 - v650;
        let v652: f64 = v643 + v651;
        let v653: f64 = v40 * v99;
        let v654: f64 = params[11];
        let v655: f64 = v654 * v38;
        let v656: f64 = v653 - v655;
        let v657: f64 = v652 + v656;
        let v658: f64 = v53 * v570;
        let v659: f64 = v50 * v636;
        let v660: f64 = v658 + v659;
        let v661: f64 = v657 + v660;
        let v662: f64 = params[10];
        let v663: f64 = v662 * v38;
        let v664: f64 = v8 * v33;
        let v665: f64 = v12 * v654;
        let v666: f64 = v664 + v665;
        let v667: f64 = v7 * v654;
        let v668: f64 = v11 * v40;
        let v669: f64 = v667 - v668;
        let v670: f64 = v11 * v669;
        let v671: f64 = v6 * v40;
        let v672: f64 = v7 * v33;
        let v673: f64 = v671 - v672;
        let v674: f64 = v6 * v673;
        let v675: f64 = v670 - v674;
        let v676: f64 = v666 + v675;
        let v677: f64 = v663 + v676;
        let v678: f64 = v677 - v621;
        let v679: f64 = v34 * v678;
        let v680: f64 = v661 - v679;
        let v681: f64 = v4 * v680;
        let v682: f64 = v640 + v681;
        let v683: f64 = v0 - v682;
        let v684: f64 = v259 * v283;
        let v685: f64 = v262 * v287;
        let v686: f64 = v684 - v685;
        let v687: f64 = v197 * v686;
        let v688: f64 = v200 * v290;
        let v689: f64 = v687 - v688;
        let v690: f64 = v127 * v689;
        let v691: f64 = v262 * v283;
        let v692: f64 = v259 * v287;
        let v693: f64 = v691 + v692;
        let v694: f64 = v130 * v693;
        let v695: f64 = v690 - v694;
        let v696: f64 = v259 * v335;
        let v697: f64 = v262 * v304;
        let v698: f64 = v696 - v697;
        let v699: f64 = v127 * v698;
        let v700: f64 = v259 * v304;
        let v701: f64 = v262 * v335;
        let v702: f64 = v700 + v701;
        let v703: f64 = v197 * v702;
        let v704: f64 = v130 * v703;
        let v705: f64 = v699 - v704;
        let v706: f64 = v34 * v705;
        let v707: f64 = v695 - v706;
        let v708: f64 = v50 * v707;
        let v709: f64 = v200 * v686;
        let v710: f64 = v197 * v290;
        let v711: f64 = v709 + v710;
        let v712: f64 = v53 * v711;
        let v713: f64 = v708 - v712;
        let v714: f64 = 0.15005_f64;
        let v715: f64 = v127 * v703;
        let v716: f64 = v130 * v698;
        let v717: f64 = v715 + v716;
        let v718: f64 = v53 * v717;
        let v719: f64 = v200 * v702;
        let v720: f64 = v50 * v719;
        let v721: f64 = v718 + v720;
        let v722: f64 = v714 * v721;
        let v723: f64 = v104 * v53;
        let v724: f64 = v723 * v705;
        let v725: f64 = v722 - v724;
        let v726: f64 = v713 + v725;
        let v727: f64 = v2 * v726;
        let v728: f64 = v53 * v707;
        let v729: f64 = v50 * v711;
        let v730: f64 = v728 + v729;
        let v731: f64 = v53 * v719;
        let v732: f64 = v50 * v717;
        let v733: f64 = v731 - v732;
        let v734: f64 = v714 * v733;
        let v735: f64 = v104 * v50;
        let v736: f64 = v735 * v705;
        let v737: f64 = v734 + v736;
        let v738: f64 = v730 + v737;
        let v739: f64 = v4 * v738;
        let v740: f64 = v727 + v739;
        let v741: f64 = v34 * v4;
        let v742: f64 = v741 * v705;
        let v743: f64 = v740 + v742;
        let v744: f64 = v743 / v290;
        let v745: f64 = tau[5];
        let v746: f64 = v745 - v374;
        let v747: f64 = v744 * v746;
        let v748: f64 = v683 - v747;
        let v749: f64 = v283 * v262;
        let v750: f64 = v287 * v259;
        let v751: f64 = v749 + v750;
        let v752: f64 = v226 + v751;
        let v753: f64 = v200 * v752;
        let v754: f64 = v259 * v260;
        let v755: f64 = v262 * v272;
        let v756: f64 = v754 - v755;
        let v757: f64 = v756 * v262;
        let v758: f64 = v259 * v272;
        let v759: f64 = v262 * v296;
        let v760: f64 = v758 - v759;
        let v761: f64 = v760 * v259;
        let v762: f64 = v757 + v761;
        let v763: f64 = v210 + v762;
        let v764: f64 = v197 * v763;
        let v765: f64 = v753 - v764;
        let v766: f64 = v127 * v765;
        let v767: f64 = v262 * v260;
        let v768: f64 = v767 + v758;
        let v769: f64 = v768 * v262;
        let v770: f64 = v259 * v296;
        let v771: f64 = v755 + v770;
        let v772: f64 = v771 * v259;
        let v773: f64 = v769 + v772;
        let v774: f64 = v234 + v773;
        let v775: f64 = v130 * v774;
        let v776: f64 = v766 + v775;
        let v777: f64 = v254 + v306;
        let v778: f64 = v197 * v777;
        let v779: f64 = v357 + v698;
        let v780: f64 = v200 * v779;
        let v781: f64 = v778 + v780;
        let v782: f64 = v130 * v781;
        let v783: f64 = v34 * v782;
        let v784: f64 = v776 + v783;
        let v785: f64 = v50 * v784;
        let v786: f64 = v200 * v763;
        let v787: f64 = v197 * v752;
        let v788: f64 = v786 + v787;
        let v789: f64 = v53 * v788;
        let v790: f64 = v785 + v789;
        let v791: f64 = v723 * v782;
        let v792: f64 = v197 * v779;
        let v793: f64 = v200 * v777;
        let v794: f64 = v792 - v793;
        let v795: f64 = v50 * v794;
        (
            v604,
            v633,
            v648,
            v654,
            v662,
            v673,
            v686,
            v689,
            v693,
            v700,
            v701,
            v711,
            v714,
            v717,
            v719,
            v721,
            v723,
            v733,
            v735,
            v741,
            v743,
            v744,
            v746,
            v748,
            v753,
            v756,
            v760,
            v764,
            v765,
            v768,
            v771,
            v774,
            v778,
            v780,
            v781,
            v782,
            v784,
            v788,
            v790,
            v791,
            v794,
            v795,
        )
    };
    let (
        v796,
        v798,
        v808,
        v817,
        v819,
        v821,
        v822,
        v826,
        v848,
        v858,
        v860,
        v880,
        v886,
        v887,
        v895,
        v904,
        v909,
        v911,
        v915,
        v916,
        v922,
        v924,
        v926,
        v931,
        v936,
        v938,
        v941,
        v943,
        v945,
        v948,
        v954,
        v956,
        v962,
        v965,
        v966,
        v968,
        v969,
        v970,
        v973,
        v977,
        v978,
        v983,
        v985,
        v987,
        v991,
        v994,
    ) = {
        let v796: f64 = v127 * v781;
        let v797: f64 = v53 * v796;
        let v798: f64 = v795 - v797;
        let v799: f64 = v714 * v798;
        let v800: f64 = v791 - v799;
        let v801: f64 = v790 + v800;
        let v802: f64 = v2 * v801;
        let v803: f64 = v53 * v784;
        let v804: f64 = v50 * v788;
        let v805: f64 = v803 - v804;
        let v806: f64 = v50 * v796;
        let v807: f64 = v53 * v794;
        let v808: f64 = v806 + v807;
        let v809: f64 = v714 * v808;
        let v810: f64 = v735 * v782;
        let v811: f64 = v809 + v810;
        let v812: f64 = v805 - v811;
        let v813: f64 = v4 * v812;
        let v814: f64 = v802 + v813;
        let v815: f64 = v741 * v782;
        let v816: f64 = v814 - v815;
        let v817: f64 = v693 / v290;
        let v818: f64 = v743 * v817;
        let v819: f64 = v816 + v818;
        let v820: f64 = v693 * v817;
        let v821: f64 = v774 - v820;
        let v822: f64 = v819 / v821;
        let v823: f64 = tau[4];
        let v824: f64 = v823 + v482;
        let v825: f64 = v817 * v746;
        let v826: f64 = v824 + v825;
        let v827: f64 = v822 * v826;
        let v828: f64 = v748 - v827;
        let v829: f64 = v756 * v259;
        let v830: f64 = v760 * v262;
        let v831: f64 = v829 - v830;
        let v832: f64 = v198 + v831;
        let v833: f64 = v197 * v832;
        let v834: f64 = v283 * v259;
        let v835: f64 = v287 * v262;
        let v836: f64 = v834 - v835;
        let v837: f64 = v213 + v836;
        let v838: f64 = v200 * v837;
        let v839: f64 = v833 - v838;
        let v840: f64 = v839 * v200;
        let v841: f64 = v213 + v686;
        let v842: f64 = v197 * v841;
        let v843: f64 = v229 + v290;
        let v844: f64 = v200 * v843;
        let v845: f64 = v842 - v844;
        let v846: f64 = v845 * v197;
        let v847: f64 = v840 + v846;
        let v848: f64 = v138 + v847;
        let v849: f64 = v127 * v848;
        let v850: f64 = v768 * v259;
        let v851: f64 = v771 * v262;
        let v852: f64 = v850 - v851;
        let v853: f64 = v210 + v852;
        let v854: f64 = v853 * v200;
        let v855: f64 = v226 + v693;
        let v856: f64 = v855 * v197;
        let v857: f64 = v854 + v856;
        let v858: f64 = v152 - v857;
        let v859: f64 = v130 * v858;
        let v860: f64 = v849 + v859;
        let v861: f64 = v701 + v700;
        let v862: f64 = v242 + v861;
        let v863: f64 = v187 - v862;
        let v864: f64 = v130 * v863;
        let v865: f64 = v382 + v794;
        let v866: f64 = v127 * v865;
        let v867: f64 = v864 + v866;
        let v868: f64 = v34 * v867;
        let v869: f64 = v860 - v868;
        let v870: f64 = v50 * v869;
        let v871: f64 = v200 * v832;
        let v872: f64 = v197 * v837;
        let v873: f64 = v871 + v872;
        let v874: f64 = v873 * v200;
        let v875: f64 = v200 * v841;
        let v876: f64 = v197 * v843;
        let v877: f64 = v875 + v876;
        let v878: f64 = v877 * v197;
        let v879: f64 = v874 + v878;
        let v880: f64 = v160 + v879;
        let v881: f64 = v53 * v880;
        let v882: f64 = v870 - v881;
        let v883: f64 = v723 * v867;
        let v884: f64 = v127 * v863;
        let v885: f64 = v130 * v865;
        let v886: f64 = v884 - v885;
        let v887: f64 = v53 * v886;
        let v888: f64 = v714 * v887;
        let v889: f64 = v883 + v888;
        let v890: f64 = v882 - v889;
        let v891: f64 = v2 * v890;
        let v892: f64 = v53 * v869;
        let v893: f64 = v50 * v880;
        let v894: f64 = v892 + v893;
        let v895: f64 = v50 * v886;
        let v896: f64 = v714 * v895;
        let v897: f64 = v735 * v867;
        let v898: f64 = v896 + v897;
        let v899: f64 = v894 + v898;
        let v900: f64 = v4 * v899;
        let v901: f64 = v891 + v900;
        let v902: f64 = v741 * v867;
        let v903: f64 = v901 + v902;
        let v904: f64 = v711 / v290;
        let v905: f64 = v743 * v904;
        let v906: f64 = v903 - v905;
        let v907: f64 = v711 * v817;
        let v908: f64 = v907 - v788;
        let v909: f64 = v908 / v821;
        let v910: f64 = v819 * v909;
        let v911: f64 = v906 - v910;
        let v912: f64 = v711 * v904;
        let v913: f64 = v880 - v912;
        let v914: f64 = v908 * v909;
        let v915: f64 = v913 - v914;
        let v916: f64 = v911 / v915;
        let v917: f64 = tau[3];
        let v918: f64 = v917 - v604;
        let v919: f64 = v904 * v746;
        let v920: f64 = v918 - v919;
        let v921: f64 = v909 * v826;
        let v922: f64 = v920 - v921;
        let v923: f64 = v916 * v922;
        let v924: f64 = v828 - v923;
        let v925: f64 = v885 - v884;
        let v926: f64 = v93 + v925;
        let v927: f64 = v104 * v926;
        let v928: f64 = v839 * v197;
        let v929: f64 = v845 * v200;
        let v930: f64 = v928 - v929;
        let v931: f64 = v128 + v930;
        let v932: f64 = v127 * v931;
        let v933: f64 = v855 * v200;
        let v934: f64 = v853 * v197;
        let v935: f64 = v933 - v934;
        let v936: f64 = v141 + v935;
        let v937: f64 = v130 * v936;
        let v938: f64 = v932 + v937;
        let v939: f64 = v938 * v130;
        let v940: f64 = v764 - v753;
        let v941: f64 = v141 - v940;
        let v942: f64 = v127 * v941;
        let v943: f64 = v155 + v774;
        let v944: f64 = v130 * v943;
        let v945: f64 = v942 + v944;
        let v946: f64 = v945 * v127;
        let v947: f64 = v939 - v946;
        let v948: f64 = v83 + v947;
        let v949: f64 = v927 - v948;
        let v950: f64 = v50 * v949;
        let v951: f64 = v873 * v197;
        let v952: f64 = v877 * v200;
        let v953: f64 = v951 - v952;
        let v954: f64 = v138 + v953;
        let v955: f64 = v954 * v130;
        let v956: f64 = v152 - v788;
        let v957: f64 = v956 * v127;
        let v958: f64 = v955 - v957;
        let v959: f64 = v34 * v925;
        let v960: f64 = v958 - v959;
        let v961: f64 = v76 + v960;
        let v962: f64 = v53 * v961;
        let v963: f64 = v950 + v962;
        let v964: f64 = v427 + v396;
        let v965: f64 = v379 + v964;
        let v966: f64 = v540 + v965;
        let v967: f64 = v104 * v966;
        let v968: f64 = v866 + v864;
        let v969: f64 = v543 + v968;
        let v970: f64 = v967 + v969;
        let v971: f64 = v50 * v970;
        let v972: f64 = v780 + v778;
        let v973: f64 = v168 + v972;
        let v974: f64 = v34 * v965;
        let v975: f64 = v973 + v974;
        let v976: f64 = v113 + v975;
        let v977: f64 = v53 * v976;
        let v978: f64 = v971 - v977;
        let v979: f64 = v714 * v978;
        let v980: f64 = v963 - v979;
        let v981: f64 = v2 * v980;
        let v982: f64 = v53 * v949;
        let v983: f64 = v50 * v961;
        let v984: f64 = v982 - v983;
        let v985: f64 = v50 * v976;
        let v986: f64 = v53 * v970;
        let v987: f64 = v985 + v986;
        let v988: f64 = v714 * v987;
        let v989: f64 = v984 - v988;
        let v990: f64 = v4 * v989;
        let v991: f64 = v981 + v990;
        let v992: f64 = v130 * v689;
        let v993: f64 = v127 * v693;
        let v994: f64 = v992 + v993;
        (
            v796,
            v798,
            v808,
            v817,
            v819,
            v821,
            v822,
            v826,
            v848,
            v858,
            v860,
            v880,
            v886,
            v887,
            v895,
            v904,
            v909,
            v911,
            v915,
            v916,
            v922,
            v924,
            v926,
            v931,
            v936,
            v938,
            v941,
            v943,
            v945,
            v948,
            v954,
            v956,
            v962,
            v965,
            v966,
            v968,
            v969,
            v970,
            v973,
            v977,
            v978,
            v983,
            v985,
            v987,
            v991,
            v994,
        )
    };
    let (
        v999,
        v1011,
        v1023,
        v1025,
        v1036,
        v1037,
        v1038,
        v1040,
        v1052,
        v1053,
        v1071,
        v1078,
        v1080,
        v1088,
        v1106,
        v1119,
        v1130,
        v1142,
        v1143,
        v1157,
        v1158,
        v1160,
        v1161,
        v1162,
        v1167,
        v1168,
        v1173,
        v1182,
        v1185,
        v1193,
    ) = {
        let v995: f64 = v34 * v717;
        let v996: f64 = v994 - v995;
        let v997: f64 = v104 * v719;
        let v998: f64 = v996 + v997;
        let v999: f64 = v998 / v290;
        let v1000: f64 = v743 * v999;
        let v1001: f64 = v991 + v1000;
        let v1002: f64 = v104 * v794;
        let v1003: f64 = v130 * v765;
        let v1004: f64 = v127 * v774;
        let v1005: f64 = v1003 - v1004;
        let v1006: f64 = v34 * v796;
        let v1007: f64 = v1005 - v1006;
        let v1008: f64 = v1002 - v1007;
        let v1009: f64 = v998 * v817;
        let v1010: f64 = v1008 - v1009;
        let v1011: f64 = v1010 / v821;
        let v1012: f64 = v819 * v1011;
        let v1013: f64 = v1001 - v1012;
        let v1014: f64 = v998 * v904;
        let v1015: f64 = v130 * v848;
        let v1016: f64 = v127 * v858;
        let v1017: f64 = v1015 - v1016;
        let v1018: f64 = v34 * v886;
        let v1019: f64 = v1017 + v1018;
        let v1020: f64 = v1014 - v1019;
        let v1021: f64 = v1010 * v909;
        let v1022: f64 = v1020 - v1021;
        let v1023: f64 = v1022 / v915;
        let v1024: f64 = v911 * v1023;
        let v1025: f64 = v1013 - v1024;
        let v1026: f64 = v130 * v931;
        let v1027: f64 = v127 * v936;
        let v1028: f64 = v1026 - v1027;
        let v1029: f64 = v1028 * v130;
        let v1030: f64 = v130 * v941;
        let v1031: f64 = v127 * v943;
        let v1032: f64 = v1030 - v1031;
        let v1033: f64 = v1032 * v127;
        let v1034: f64 = v1029 - v1033;
        let v1035: f64 = 0.18645124000000002_f64;
        let v1036: f64 = v1035 * v965;
        let v1037: f64 = 2.0_f64;
        let v1038: f64 = v34 * v973;
        let v1039: f64 = v1037 * v1038;
        let v1040: f64 = v1036 + v1039;
        let v1041: f64 = v1034 + v1040;
        let v1042: f64 = v85 + v1041;
        let v1043: f64 = v104 * v969;
        let v1044: f64 = v1042 + v1043;
        let v1045: f64 = v104 * v970;
        let v1046: f64 = v1044 + v1045;
        let v1047: f64 = v998 * v999;
        let v1048: f64 = v1046 - v1047;
        let v1049: f64 = v1010 * v1011;
        let v1050: f64 = v1048 - v1049;
        let v1051: f64 = v1022 * v1023;
        let v1052: f64 = v1050 - v1051;
        let v1053: f64 = v1025 / v1052;
        let v1054: f64 = tau[2];
        let v1055: f64 = v83 * v61;
        let v1056: f64 = v76 * v71;
        let v1057: f64 = v1055 - v1056;
        let v1058: f64 = v58 * v580;
        let v1059: f64 = v69 * v81;
        let v1060: f64 = v1058 - v1059;
        let v1061: f64 = v1057 + v1060;
        let v1062: f64 = v113 * v177;
        let v1063: f64 = v543 * v111;
        let v1064: f64 = v1062 - v1063;
        let v1065: f64 = v1061 + v1064;
        let v1066: f64 = v130 * v446;
        let v1067: f64 = v127 * v536;
        let v1068: f64 = v1066 - v1067;
        let v1069: f64 = v1065 + v1068;
        let v1070: f64 = v104 * v568;
        let v1071: f64 = v1069 - v1070;
        let v1072: f64 = v1054 + v1071;
        let v1073: f64 = v999 * v746;
        let v1074: f64 = v1072 + v1073;
        let v1075: f64 = v1011 * v826;
        let v1076: f64 = v1074 - v1075;
        let v1077: f64 = v1023 * v922;
        let v1078: f64 = v1076 - v1077;
        let v1079: f64 = v1053 * v1078;
        let v1080: f64 = v924 - v1079;
        let v1081: f64 = v735 * v926;
        let v1082: f64 = v50 * v948;
        let v1083: f64 = v1082 - v962;
        let v1084: f64 = v714 * v735;
        let v1085: f64 = v966 * v1084;
        let v1086: f64 = v1083 + v1085;
        let v1087: f64 = v50 * v969;
        let v1088: f64 = v1087 - v977;
        let v1089: f64 = v714 * v1088;
        let v1090: f64 = v1086 + v1089;
        let v1091: f64 = v1081 - v1090;
        let v1092: f64 = v15 + v1091;
        let v1093: f64 = v714 * v966;
        let v1094: f64 = v1093 - v926;
        let v1095: f64 = v40 + v1094;
        let v1096: f64 = v34 * v1095;
        let v1097: f64 = v1092 - v1096;
        let v1098: f64 = v2 * v1097;
        let v1099: f64 = v723 * v926;
        let v1100: f64 = v53 * v948;
        let v1101: f64 = v1100 + v983;
        let v1102: f64 = v714 * v723;
        let v1103: f64 = v966 * v1102;
        let v1104: f64 = v1101 + v1103;
        let v1105: f64 = v53 * v969;
        let v1106: f64 = v1105 + v985;
        let v1107: f64 = v714 * v1106;
        let v1108: f64 = v1104 + v1107;
        let v1109: f64 = v1099 - v1108;
        let v1110: f64 = v17 + v1109;
        let v1111: f64 = v4 * v1110;
        let v1112: f64 = v1098 + v1111;
        let v1113: f64 = v735 * v721;
        let v1114: f64 = v723 * v733;
        let v1115: f64 = v1113 + v1114;
        let v1116: f64 = v996 + v1115;
        let v1117: f64 = v34 * v721;
        let v1118: f64 = v1116 + v1117;
        let v1119: f64 = v1118 / v290;
        let v1120: f64 = v743 * v1119;
        let v1121: f64 = v1112 + v1120;
        let v1122: f64 = v735 * v798;
        let v1123: f64 = v723 * v808;
        let v1124: f64 = v1122 + v1123;
        let v1125: f64 = v1124 - v1007;
        let v1126: f64 = v34 * v798;
        let v1127: f64 = v1125 + v1126;
        let v1128: f64 = v1118 * v817;
        let v1129: f64 = v1127 - v1128;
        let v1130: f64 = v1129 / v821;
        let v1131: f64 = v819 * v1130;
        let v1132: f64 = v1121 - v1131;
        let v1133: f64 = v735 * v887;
        let v1134: f64 = v723 * v895;
        let v1135: f64 = v1133 - v1134;
        let v1136: f64 = v1135 - v1019;
        let v1137: f64 = v34 * v887;
        let v1138: f64 = v1136 + v1137;
        let v1139: f64 = v1118 * v904;
        let v1140: f64 = v1138 + v1139;
        let v1141: f64 = v1129 * v909;
        let v1142: f64 = v1140 - v1141;
        let v1143: f64 = v1142 / v915;
        let v1144: f64 = v911 * v1143;
        let v1145: f64 = v1132 - v1144;
        let v1146: f64 = v735 * v978;
        let v1147: f64 = v723 * v987;
        let v1148: f64 = v1146 + v1147;
        let v1149: f64 = v1044 + v1148;
        let v1150: f64 = v34 * v978;
        let v1151: f64 = v1149 + v1150;
        let v1152: f64 = v1118 * v999;
        let v1153: f64 = v1151 - v1152;
        let v1154: f64 = v1129 * v1011;
        let v1155: f64 = v1153 - v1154;
        let v1156: f64 = v1142 * v1023;
        let v1157: f64 = v1155 - v1156;
        let v1158: f64 = v1157 / v1052;
        let v1159: f64 = v1025 * v1158;
        let v1160: f64 = v1145 - v1159;
        let v1161: f64 = v735 * v735;
        let v1162: f64 = v723 * v723;
        let v1163: f64 = v1161 + v1162;
        let v1164: f64 = 0.022515002499999996_f64;
        let v1165: f64 = v1163 + v1164;
        let v1166: f64 = v966 * v1165;
        let v1167: f64 = v1088 * v735;
        let v1168: f64 = v1106 * v723;
        let v1169: f64 = v1167 + v1168;
        let v1170: f64 = v714 * v926;
        let v1171: f64 = v1169 - v1170;
        let v1172: f64 = v1037 * v1171;
        let v1173: f64 = v1166 + v1172;
        let v1174: f64 = v1042 + v1173;
        let v1175: f64 = v1164 * v966;
        let v1176: f64 = v1174 - v1175;
        let v1177: f64 = v1176 + v1170;
        let v1178: f64 = v1177 + v1170;
        let v1179: f64 = v20 + v1178;
        let v1180: f64 = v966 * v735;
        let v1181: f64 = v1088 + v1180;
        let v1182: f64 = v654 + v1181;
        let v1183: f64 = v34 * v1182;
        let v1184: f64 = v1179 + v1183;
        let v1185: f64 = v662 + v966;
        let v1186: f64 = v34 * v1185;
        let v1187: f64 = v1186 + v1182;
        let v1188: f64 = v34 * v1187;
        let v1189: f64 = v1184 + v1188;
        let v1190: f64 = v1118 * v1119;
        let v1191: f64 = v1189 - v1190;
        let v1192: f64 = v1129 * v1130;
        let v1193: f64 = v1191 - v1192;
        (
            v999,
            v1011,
            v1023,
            v1025,
            v1036,
            v1037,
            v1038,
            v1040,
            v1052,
            v1053,
            v1071,
            v1078,
            v1080,
            v1088,
            v1106,
            v1119,
            v1130,
            v1142,
            v1143,
            v1157,
            v1158,
            v1160,
            v1161,
            v1162,
            v1167,
            v1168,
            v1173,
            v1182,
            v1185,
            v1193,
        )
    };
    let (v1357, v1360, v1365, v1372, v1381, v1392) = {
        let v1194: f64 = v1142 * v1143;
        let v1195: f64 = v1193 - v1194;
        let v1196: f64 = v1157 * v1158;
        let v1197: f64 = v1195 - v1196;
        let v1198: f64 = v1160 / v1197;
        let v1199: f64 = tau[1];
        let v1200: f64 = v15 * v8;
        let v1201: f64 = v17 * v12;
        let v1202: f64 = v1200 - v1201;
        let v1203: f64 = v11 * v29;
        let v1204: f64 = v6 * v648;
        let v1205: f64 = v1203 - v1204;
        let v1206: f64 = v1202 + v1205;
        let v1207: f64 = v654 * v45;
        let v1208: f64 = v33 * v99;
        let v1209: f64 = v1207 - v1208;
        let v1210: f64 = v1206 + v1209;
        let v1211: f64 = v1210 - v1071;
        let v1212: f64 = v662 * v45;
        let v1213: f64 = v7 * v673;
        let v1214: f64 = v11 * v33;
        let v1215: f64 = v6 * v654;
        let v1216: f64 = v1214 - v1215;
        let v1217: f64 = v11 * v1216;
        let v1218: f64 = v1213 - v1217;
        let v1219: f64 = v8 * v40;
        let v1220: f64 = v1218 - v1219;
        let v1221: f64 = v1212 + v1220;
        let v1222: f64 = v53 * v633;
        let v1223: f64 = v50 * v568;
        let v1224: f64 = v1222 + v1223;
        let v1225: f64 = v1221 + v1224;
        let v1226: f64 = v34 * v1225;
        let v1227: f64 = v1211 + v1226;
        let v1228: f64 = v1199 - v1227;
        let v1229: f64 = v1119 * v746;
        let v1230: f64 = v1228 + v1229;
        let v1231: f64 = v1130 * v826;
        let v1232: f64 = v1230 - v1231;
        let v1233: f64 = v1143 * v922;
        let v1234: f64 = v1232 - v1233;
        let v1235: f64 = v1158 * v1078;
        let v1236: f64 = v1234 - v1235;
        let v1237: f64 = v1198 * v1236;
        let v1238: f64 = v1080 - v1237;
        let v1239: f64 = params[7];
        let v1240: f64 = v938 * v127;
        let v1241: f64 = v945 * v130;
        let v1242: f64 = v1240 + v1241;
        let v1243: f64 = v1242 + v1040;
        let v1244: f64 = v51 + v1243;
        let v1245: f64 = v50 * v1244;
        let v1246: f64 = v954 * v127;
        let v1247: f64 = v956 * v130;
        let v1248: f64 = v1246 + v1247;
        let v1249: f64 = v34 * v968;
        let v1250: f64 = v1248 - v1249;
        let v1251: f64 = v63 + v1250;
        let v1252: f64 = v53 * v1251;
        let v1253: f64 = v1245 - v1252;
        let v1254: f64 = v1253 * v50;
        let v1255: f64 = v860 - v1249;
        let v1256: f64 = v63 + v1255;
        let v1257: f64 = v50 * v1256;
        let v1258: f64 = v880 + v1040;
        let v1259: f64 = v1258 - v1036;
        let v1260: f64 = v1259 - v1038;
        let v1261: f64 = v1260 - v1038;
        let v1262: f64 = v79 + v1261;
        let v1263: f64 = v53 * v1262;
        let v1264: f64 = v1257 - v1263;
        let v1265: f64 = v1264 * v53;
        let v1266: f64 = v1254 - v1265;
        let v1267: f64 = v1266 + v1173;
        let v1268: f64 = v966 * v1161;
        let v1269: f64 = v1267 - v1268;
        let v1270: f64 = v1269 - v1167;
        let v1271: f64 = v735 * v1088;
        let v1272: f64 = v1270 - v1271;
        let v1273: f64 = v3 + v1272;
        let v1274: f64 = v2 * v1273;
        let v1275: f64 = v53 * v1244;
        let v1276: f64 = v50 * v1251;
        let v1277: f64 = v1275 + v1276;
        let v1278: f64 = v1277 * v50;
        let v1279: f64 = v53 * v1256;
        let v1280: f64 = v50 * v1262;
        let v1281: f64 = v1279 + v1280;
        let v1282: f64 = v1281 * v53;
        let v1283: f64 = v1278 - v1282;
        let v1284: f64 = v723 * v735;
        let v1285: f64 = v966 * v1284;
        let v1286: f64 = v1283 - v1285;
        let v1287: f64 = v1106 * v735;
        let v1288: f64 = v1286 - v1287;
        let v1289: f64 = v723 * v1088;
        let v1290: f64 = v1288 - v1289;
        let v1291: f64 = v10 + v1290;
        let v1292: f64 = v4 * v1291;
        let v1293: f64 = v1274 + v1292;
        let v1294: f64 = v1293 * v2;
        let v1295: f64 = v1253 * v53;
        let v1296: f64 = v1264 * v50;
        let v1297: f64 = v1295 + v1296;
        let v1298: f64 = v735 * v723;
        let v1299: f64 = v966 * v1298;
        let v1300: f64 = v1297 - v1299;
        let v1301: f64 = v1088 * v723;
        let v1302: f64 = v1300 - v1301;
        let v1303: f64 = v735 * v1106;
        let v1304: f64 = v1302 - v1303;
        let v1305: f64 = v10 + v1304;
        let v1306: f64 = v2 * v1305;
        let v1307: f64 = v1277 * v53;
        let v1308: f64 = v1281 * v50;
        let v1309: f64 = v1307 + v1308;
        let v1310: f64 = v1309 + v1173;
        let v1311: f64 = v966 * v1162;
        let v1312: f64 = v1310 - v1311;
        let v1313: f64 = v1312 - v1168;
        let v1314: f64 = v723 * v1106;
        let v1315: f64 = v1313 - v1314;
        let v1316: f64 = v25 + v1315;
        let v1317: f64 = v4 * v1316;
        let v1318: f64 = v1306 + v1317;
        let v1319: f64 = v1318 * v4;
        let v1320: f64 = v1294 + v1319;
        let v1321: f64 = v741 * v741;
        let v1322: f64 = v34 * v2;
        let v1323: f64 = v1322 * v1322;
        let v1324: f64 = v1321 + v1323;
        let v1325: f64 = v1185 * v1324;
        let v1326: f64 = v4 * v1182;
        let v1327: f64 = v966 * v723;
        let v1328: f64 = v1106 + v1327;
        let v1329: f64 = v33 + v1328;
        let v1330: f64 = v2 * v1329;
        let v1331: f64 = v1326 - v1330;
        let v1332: f64 = v1331 * v741;
        let v1333: f64 = v2 * v1182;
        let v1334: f64 = v4 * v1329;
        let v1335: f64 = v1333 + v1334;
        let v1336: f64 = v1335 * v1322;
        let v1337: f64 = v1332 + v1336;
        let v1338: f64 = v1037 * v1337;
        let v1339: f64 = v1325 + v1338;
        let v1340: f64 = v1320 + v1339;
        let v1341: f64 = v1185 * v1323;
        let v1342: f64 = v1340 - v1341;
        let v1343: f64 = v1342 - v1336;
        let v1344: f64 = v1322 * v1335;
        let v1345: f64 = v1343 - v1344;
        let v1346: f64 = v1239 + v1345;
        let v1347: f64 = v743 * v744;
        let v1348: f64 = v1346 - v1347;
        let v1349: f64 = v819 * v822;
        let v1350: f64 = v1348 - v1349;
        let v1351: f64 = v911 * v916;
        let v1352: f64 = v1350 - v1351;
        let v1353: f64 = v1025 * v1053;
        let v1354: f64 = v1352 - v1353;
        let v1355: f64 = v1160 * v1198;
        let v1356: f64 = v1354 - v1355;
        let v1357: f64 = v1238 / v1356;
        let v1358: f64 = v1236 / v1197;
        let v1359: f64 = v1198 * v1357;
        let v1360: f64 = v1358 - v1359;
        let v1361: f64 = v1078 / v1052;
        let v1362: f64 = v1053 * v1357;
        let v1363: f64 = v1361 - v1362;
        let v1364: f64 = v1158 * v1360;
        let v1365: f64 = v1363 - v1364;
        let v1366: f64 = v922 / v915;
        let v1367: f64 = v916 * v1357;
        let v1368: f64 = v1366 - v1367;
        let v1369: f64 = v1143 * v1360;
        let v1370: f64 = v1368 - v1369;
        let v1371: f64 = v1023 * v1365;
        let v1372: f64 = v1370 - v1371;
        let v1373: f64 = v826 / v821;
        let v1374: f64 = v822 * v1357;
        let v1375: f64 = v1373 - v1374;
        let v1376: f64 = v1130 * v1360;
        let v1377: f64 = v1375 - v1376;
        let v1378: f64 = v1011 * v1365;
        let v1379: f64 = v1377 - v1378;
        let v1380: f64 = v909 * v1372;
        let v1381: f64 = v1379 - v1380;
        let v1382: f64 = v746 / v290;
        let v1383: f64 = v744 * v1357;
        let v1384: f64 = v1382 - v1383;
        let v1385: f64 = v1119 * v1360;
        let v1386: f64 = v1384 + v1385;
        let v1387: f64 = v999 * v1365;
        let v1388: f64 = v1386 + v1387;
        let v1389: f64 = v904 * v1372;
        let v1390: f64 = v1388 - v1389;
        let v1391: f64 = v817 * v1381;
        let v1392: f64 = v1390 + v1391;
        (v1357, v1360, v1365, v1372, v1381, v1392)
    };
    [v1357, v1360, v1365, v1372, v1381, v1392]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/puma560_parametric.json")
);
