//! The single-precision functions (`armdyn_generated::<robot>::f32`) against the `f64` ones,
//! for every generated robot, over random states within the joint limits.
//!
//! Per state and function the error is `max_i |y32_i - y64_i| / max_i |y64_i|`: the largest
//! element error relative to the largest element of the `f64` output (its max norm), with the
//! inputs rounded to `f32` for the `f32` call. States: `q` uniform within `JOINT_LIMITS`,
//! `qd` uniform in `[-2, 2]` (rad/s, m/s), `tau = ID(q, qd, qdd)` with `qdd` uniform in
//! `[-5, 5]` (rad/s^2, m/s^2). The bounds below are a small factor above the worst case
//! measured over all robots (`cargo test --release --test model generated_f32 -- --nocapture`
//! prints it per robot and function).

use approx::assert_abs_diff_eq;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// States per robot.
const STATES: usize = 1000;
/// Seed of the random states.
const SEED: u64 = 0x0F32_2026_1130;

/// Bound on the relative error of `M(q)` (measured worst 4.2e-7, the Panda).
const BOUND_MASS_MATRIX: f64 = 1e-6;
/// Bound on the relative error of `c(q, qd)` (measured worst 3.0e-6, the PUMA 560).
const BOUND_CORIOLIS: f64 = 1e-5;
/// Bound on the relative error of `g(q)` (measured worst 6.1e-6, the UR5).
const BOUND_GRAVITY: f64 = 2e-5;
/// Bound on the relative error of `qdd = FD(q, qd, tau)` (measured worst 2.2e-5, the planar
/// 2R).
const BOUND_FORWARD_DYNAMICS: f64 = 1e-4;

/// Worst relative errors of one robot: `[M, c, g, FD]`.
type Worst = [f64; 4];

/// `f64` to `f32`, rounding to nearest.
fn single<const N: usize>(x: &[f64; N]) -> [f32; N] {
    x.map(|v| v as f32)
}

/// The relative error of `y32` against `y64`, asserting it is within `bound` (`approx`,
/// element by element, with the max norm of `y64` as the scale).
fn relative_error(what: &str, y64: &[f64], y32: &[f32], bound: f64) -> f64 {
    let scale = y64.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let scale = if scale > 0.0 { scale } else { 1.0 };
    let mut worst = 0.0f64;
    for (a, b) in y64.iter().zip(y32) {
        let b = f64::from(*b);
        assert_abs_diff_eq!(a, &b, epsilon = bound * scale);
        worst = worst.max((a - b).abs() / scale);
    }
    assert!(worst.is_finite(), "{what}: not finite");
    worst
}

macro_rules! robots {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        /// Every robot's worst errors, by name.
        fn all_robots() -> Vec<(&'static str, Worst)> {
            vec![$((stringify!($module), $module())),*]
        }

        $(
            fn $module() -> Worst {
                use armdyn_generated::$module as g;
                let mut rng = Xoshiro256PlusPlus::seed_from_u64(SEED);
                let mut worst = [0.0f64; 4];
                for _ in 0..STATES {
                    let q: [f64; $n] =
                        core::array::from_fn(|i| {
                            let [lo, hi] = g::JOINT_LIMITS[i];
                            rng.random_range(lo..=hi)
                        });
                    let qd: [f64; $n] = core::array::from_fn(|_| rng.random_range(-2.0..=2.0));
                    let qdd: [f64; $n] = core::array::from_fn(|_| rng.random_range(-5.0..=5.0));
                    let tau = g::inverse_dynamics(&q, &qd, &qdd);
                    let (q32, qd32, tau32) = (single(&q), single(&qd), single(&tau));
                    let errors = [
                        relative_error(
                            "mass_matrix",
                            g::mass_matrix(&q).as_flattened(),
                            g::f32::mass_matrix(&q32).as_flattened(),
                            BOUND_MASS_MATRIX,
                        ),
                        relative_error(
                            "coriolis",
                            &g::coriolis(&q, &qd),
                            &g::f32::coriolis(&q32, &qd32),
                            BOUND_CORIOLIS,
                        ),
                        relative_error(
                            "gravity",
                            &g::gravity(&q),
                            &g::f32::gravity(&q32),
                            BOUND_GRAVITY,
                        ),
                        relative_error(
                            "forward_dynamics",
                            &g::forward_dynamics(&q, &qd, &tau),
                            &g::f32::forward_dynamics(&q32, &qd32, &tau32),
                            BOUND_FORWARD_DYNAMICS,
                        ),
                    ];
                    for (w, e) in worst.iter_mut().zip(errors) {
                        *w = w.max(e);
                    }
                }
                worst
            }
        )*
    };
}

armdyn_generated::for_each_robot!(robots);

#[test]
fn f32_functions_stay_within_their_bounds_of_f64_for_every_robot() {
    let all = all_robots();
    assert_eq!(all.len(), armdyn_generated::ROBOTS.len());
    println!(
        "{:<10} {:>12} {:>12} {:>12} {:>12}",
        "robot", "M", "c", "g", "FD"
    );
    let mut overall = [0.0f64; 4];
    for (name, worst) in &all {
        println!(
            "{name:<10} {:>12.3e} {:>12.3e} {:>12.3e} {:>12.3e}",
            worst[0], worst[1], worst[2], worst[3]
        );
        for (o, w) in overall.iter_mut().zip(worst) {
            *o = o.max(*w);
        }
    }
    println!(
        "{:<10} {:>12.3e} {:>12.3e} {:>12.3e} {:>12.3e}",
        "worst", overall[0], overall[1], overall[2], overall[3]
    );
    println!(
        "{:<10} {:>12.3e} {:>12.3e} {:>12.3e} {:>12.3e}",
        "bound", BOUND_MASS_MATRIX, BOUND_CORIOLIS, BOUND_GRAVITY, BOUND_FORWARD_DYNAMICS
    );
    // The f32 functions are not f64 in disguise: their error is that of single precision.
    assert!(overall.iter().all(|&w| w > 1e-9), "{overall:?}");
}
