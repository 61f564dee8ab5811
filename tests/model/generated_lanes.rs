//! The lane functions (`armdyn_generated::<robot>::lanes`) against the scalar `f64` ones, for
//! every generated robot and every function, over 256 random states per robot: in `f64x4`
//! lanes (64 calls of four states) and in `f64x2` lanes to 1e-12, and over plain `f64` bit for
//! bit (the same instructions, and `libm`'s trig).
//!
//! Per state and function the error is `max_i |y4_i - y_i| / max(1, max_i |y_i|)`: the largest
//! element error relative to the scalar output's max norm (absolute below 1). The arithmetic
//! of the lanes is the scalar's instruction for instruction; only the trig differs (`wide`'s
//! vectorised `sin_cos` and `atan2` against `libm`'s, each within a few ulp), so every lane
//! equals the scalar result to a few hundred ulp. The scalar functions are checked against
//! Pinocchio and finite differences elsewhere; this ties the lanes to them. States: `q`
//! uniform within `JOINT_LIMITS`, `qd` in `[-2, 2]`, `qdd` in `[-5, 5]`, `tau = ID(q, qd,
//! qdd)`. `cargo test --release --test model generated_lanes -- --nocapture` prints the worst
//! error per robot.

use armdyn_generated::lanes::Lane;
use armdyn_generated::wide::{f64x2, f64x4};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// Random states per robot (a multiple of 4).
const STATES: usize = 256;
/// Seed of the random states.
const SEED: u64 = 0x0F64_0004_2026;
/// Bound on every function's relative error in SIMD lanes (measured worst 2.8e-14, the
/// Panda's forward dynamics, in both `f64x4` and `f64x2`).
const BOUND: f64 = 1e-12;

/// `L::LANES` states in lanes: lane `k` of entry `i` is `states[k][i]`.
fn pack<L: Lane, const N: usize>(states: &[[f64; N]]) -> [L; N] {
    core::array::from_fn(|i| L::from_fn(|k| states[k][i]))
}

/// The error of lane `k` of `lanes` against the scalar output `scalar` (both flattened),
/// checked finite and within `bound`.
fn lane_error<L: Lane>(what: &str, lanes: &[L], scalar: &[f64], k: usize, bound: f64) -> f64 {
    assert_eq!(lanes.len(), scalar.len(), "{what}: shapes differ");
    let scale = scalar.iter().fold(1.0f64, |a, v| a.max(v.abs()));
    let error = lanes
        .iter()
        .zip(scalar)
        .map(|(l, s)| (l.lane(k) - s).abs())
        .fold(0.0f64, f64::max)
        / scale;
    assert!(error.is_finite(), "{what}, lane {k}: not finite");
    assert!(
        error <= bound,
        "{what}, lane {k}: error {error:e} above {bound:e}"
    );
    error
}

macro_rules! robots {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        /// Every robot's worst error over all its functions in `L` lanes, with the function.
        fn all_robots<L: Lane>(bound: f64) -> Vec<(&'static str, f64, &'static str)> {
            vec![$({ let (e, f) = $module::<L>(bound); (stringify!($module), e, f) }),*]
        }

        $(
            fn $module<L: Lane>(bound: f64) -> (f64, &'static str) {
                use armdyn_generated::$module as g;
                let mut rng = Xoshiro256PlusPlus::seed_from_u64(SEED);
                let mut worst = (0.0f64, "");
                let state = |rng: &mut Xoshiro256PlusPlus| {
                    let q: [f64; $n] = core::array::from_fn(|i| {
                        let [lo, hi] = g::JOINT_LIMITS[i];
                        rng.random_range(lo..=hi)
                    });
                    let qd: [f64; $n] = core::array::from_fn(|_| rng.random_range(-2.0..=2.0));
                    let qdd: [f64; $n] = core::array::from_fn(|_| rng.random_range(-5.0..=5.0));
                    (q, qd, qdd, g::inverse_dynamics(&q, &qd, &qdd))
                };
                for _ in 0..STATES / L::LANES {
                    let s: Vec<_> = (0..L::LANES).map(|_| state(&mut rng)).collect();
                    let q: [L; $n] = pack(&s.iter().map(|s| s.0).collect::<Vec<_>>());
                    let qd: [L; $n] = pack(&s.iter().map(|s| s.1).collect::<Vec<_>>());
                    let qdd: [L; $n] = pack(&s.iter().map(|s| s.2).collect::<Vec<_>>());
                    let tau: [L; $n] = pack(&s.iter().map(|s| s.3).collect::<Vec<_>>());
                    let poses = g::lanes::frame_poses(&q);
                    let pose = g::lanes::end_effector_pose(&q);
                    let jacobian = g::lanes::jacobian(&q);
                    let jp = g::lanes::jacobian_and_position(&q);
                    let jdot_qd = g::lanes::jdot_qd(&q, &qd);
                    let mass = g::lanes::mass_matrix(&q);
                    let coriolis_matrix = g::lanes::coriolis_matrix(&q, &qd);
                    let coriolis = g::lanes::coriolis(&q, &qd);
                    let gravity = g::lanes::gravity(&q);
                    let id = g::lanes::inverse_dynamics(&q, &qd, &qdd);
                    let fd = g::lanes::forward_dynamics(&q, &qd, &tau);
                    let mb = g::lanes::mass_matrix_and_bias(&q, &qd);
                    let regressor = g::lanes::regressor(&q, &qd, &qdd);
                    let parameters: [L; _] = g::lanes::standard_parameters();
                    let djacobian = g::lanes::jacobian_derivatives(&q);
                    let did = g::lanes::inverse_dynamics_derivatives(&q, &qd, &qdd);
                    let dfd = g::lanes::forward_dynamics_derivatives(&q, &qd, &tau);
                    for (k, (q1, qd1, qdd1, tau1)) in s.iter().enumerate() {
                        let e = |what: &'static str, lanes: &[L], scalar: &[f64]| {
                            (what, lane_error(what, lanes, scalar, k, bound))
                        };
                        let errors = [
                            e("frame_poses", poses.as_flattened().as_flattened(), g::frame_poses(q1).as_flattened().as_flattened()),
                            e("end_effector_pose", pose.as_flattened(), g::end_effector_pose(q1).as_flattened()),
                            e("jacobian", jacobian.as_flattened(), g::jacobian(q1).as_flattened()),
                            e("jacobian_and_position", jp.as_flattened(), g::jacobian_and_position(q1).as_flattened()),
                            e("jdot_qd", &jdot_qd, &g::jdot_qd(q1, qd1)),
                            e("mass_matrix", mass.as_flattened(), g::mass_matrix(q1).as_flattened()),
                            e("coriolis_matrix", coriolis_matrix.as_flattened(), g::coriolis_matrix(q1, qd1).as_flattened()),
                            e("coriolis", &coriolis, &g::coriolis(q1, qd1)),
                            e("gravity", &gravity, &g::gravity(q1)),
                            e("inverse_dynamics", &id, &g::inverse_dynamics(q1, qd1, qdd1)),
                            e("forward_dynamics", &fd, &g::forward_dynamics(q1, qd1, tau1)),
                            e("mass_matrix_and_bias", mb.as_flattened(), g::mass_matrix_and_bias(q1, qd1).as_flattened()),
                            e("regressor", regressor.as_flattened(), g::regressor(q1, qd1, qdd1).as_flattened()),
                            e("standard_parameters", &parameters, &g::standard_parameters()),
                            e("jacobian_derivatives", djacobian.as_flattened().as_flattened(), g::jacobian_derivatives(q1).as_flattened().as_flattened()),
                            e("inverse_dynamics_derivatives", did.as_flattened(), g::inverse_dynamics_derivatives(q1, qd1, qdd1).as_flattened()),
                            e("forward_dynamics_derivatives", dfd.as_flattened(), g::forward_dynamics_derivatives(q1, qd1, tau1).as_flattened()),
                        ];
                        for (name, e) in errors {
                            if e > worst.0 {
                                worst = (e, name);
                            }
                        }
                    }
                }
                worst
            }
        )*
    };
}

armdyn_generated::for_each_robot!(robots);

fn report(lane: &str, all: &[(&'static str, f64, &'static str)]) {
    assert_eq!(all.len(), armdyn_generated::ROBOTS.len());
    println!("{lane}: {:<10} {:>12}  function", "robot", "worst");
    for (name, worst, function) in all {
        println!("{lane}: {name:<10} {worst:>12.3e}  {function}");
    }
}

#[test]
fn simd_lanes_equal_the_scalar_functions_for_every_robot() {
    for (lane, all) in [
        ("f64x4", all_robots::<f64x4>(BOUND)),
        ("f64x2", all_robots::<f64x2>(BOUND)),
    ] {
        report(lane, &all);
        // The SIMD lanes are not the scalar functions in disguise: their trig is wide's.
        assert!(all.iter().any(|(_, w, _)| *w > 0.0), "{lane}: {all:?}");
    }
}

#[test]
fn f64_lanes_are_the_scalar_functions_bit_for_bit() {
    // Same instructions in the same order, libm's trig: no difference at all.
    report("f64", &all_robots::<f64>(0.0));
}
