//! The generated derivatives of the dynamics ([`DynamicsDerivatives`]) against central
//! differences of the generated functions, for every robot at 256 random states, with and
//! without a tool wrench; and their `f32` variants against `f64`.
//!
//! Each block `A` of a derivative is compared with its five-point central difference `A_h`,
//! column k `(8 (f(x + h e_k) - f(x - h e_k)) - (f(x + 2h e_k) - f(x - 2h e_k))) / 12h`, step
//! `h = 1e-4` (rad, m, rad/s, N m: the inputs are of order one), by
//! `max |A - A_h| / max(1, max |A|)`. The stencil's truncation error is `h^4 f^(5) / 30`,
//! about 1e-17 here, and its rounding error about `eps |f| / h`, 1e-12 |f|, so a correct
//! derivative is within about 1e-9 (measured worst printed by
//! `cargo test --release --test model derivatives -- --nocapture`); a wrong sign, a missing
//! term or a transposed block is off by the size of the block. States: `q` uniform within
//! `JOINT_LIMITS`, `qd` in `[-2, 2]`, `qdd` in `[-5, 5]`, `tau = ID(q, qd, qdd)`, the wrench
//! in `[-50, 50]` N and `[-5, 5]` N m.

use armdyn::model::{
    forward_dynamics_derivatives_with_wrench, inverse_dynamics_derivatives_with_wrench,
    DynamicsDerivatives, JointMatrix, JointVector, Wrench,
};
use nalgebra::{DMatrix, SMatrix};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// States per robot.
const STATES: usize = 256;
/// Seed of the random states.
const SEED: u64 = 0xD1FF_2026_1205;
/// Central-difference step.
const STEP: f64 = 1e-4;
/// Bound on the relative error of every block against its central difference (measured
/// worst 1.6e-7, the PUMA 560's `d qdd/d qd` under a wrench, whose wrist accelerations are
/// large; every other block below 2e-9).
const BOUND: f64 = 1e-6;

/// `max |a - b| / max(1, max |a|)`.
fn error(a: &DMatrix<f64>, b: &DMatrix<f64>) -> f64 {
    assert_eq!(a.shape(), b.shape());
    let scale = a.iter().fold(1.0f64, |s, v| s.max(v.abs()));
    let e = a
        .iter()
        .zip(b.iter())
        .map(|(x, y)| (x - y).abs())
        .fold(0.0f64, f64::max)
        / scale;
    assert!(e.is_finite(), "not finite");
    e
}

/// The central difference of `f: R^m -> R^r` at `x`, r x m.
fn central<const M: usize>(
    x: &SMatrix<f64, M, 1>,
    f: impl Fn(&SMatrix<f64, M, 1>) -> DMatrix<f64>,
) -> DMatrix<f64> {
    let rows = f(x).len();
    let mut d = DMatrix::zeros(rows, M);
    for k in 0..M {
        let at = |h: f64| {
            let mut y = *x;
            y[k] += h;
            f(&y)
        };
        let column =
            ((at(STEP) - at(-STEP)) * 8.0 - (at(2.0 * STEP) - at(-2.0 * STEP))) / (12.0 * STEP);
        d.set_column(
            k,
            &DMatrix::from_column_slice(rows, 1, column.as_slice()).column(0),
        );
    }
    d
}

fn dynamic<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> DMatrix<f64> {
    DMatrix::from_column_slice(R, C, m.as_slice())
}

/// The worst error of each check over the robot's states, by name.
fn check_robot<const N: usize, R: DynamicsDerivatives<N>>(robot: &R) -> Vec<(&'static str, f64)> {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(SEED);
    let mut worst: Vec<(&'static str, f64)> = Vec::new();
    let mut record = |name: &'static str, e: f64| {
        assert!(
            e <= BOUND,
            "{}: {name} off by {e:e} (bound {BOUND:e})",
            robot.name()
        );
        match worst.iter_mut().find(|(n, _)| *n == name) {
            Some(w) => w.1 = w.1.max(e),
            None => worst.push((name, e)),
        }
    };
    for _ in 0..STATES {
        let q = JointVector::<N>::from_fn(|i, _| {
            let [lo, hi] = R::JOINT_LIMITS[i];
            rng.random_range(lo..=hi)
        });
        let qd = JointVector::<N>::from_fn(|_, _| rng.random_range(-2.0..=2.0));
        let qdd = JointVector::<N>::from_fn(|_, _| rng.random_range(-5.0..=5.0));
        let f = Wrench::from_fn(|i, _| {
            let s = if i < 3 { 50.0 } else { 5.0 };
            rng.random_range(-s..=s)
        });
        let tau = robot.inverse_dynamics(&q, &qd, &qdd);

        let id = robot.inverse_dynamics_derivatives(&q, &qd, &qdd);
        let id_q = central(&q, |x| dynamic(&robot.inverse_dynamics(x, &qd, &qdd)));
        let id_v = central(&qd, |x| dynamic(&robot.inverse_dynamics(&q, x, &qdd)));
        record("d tau/d q", error(&dynamic(&id.dtau_dq), &id_q));
        record("d tau/d qd", error(&dynamic(&id.dtau_dqd), &id_v));
        record(
            "d tau/d qdd = M",
            error(&dynamic(&id.mass_matrix), &dynamic(&robot.mass_matrix(&q))),
        );

        let fd = robot.forward_dynamics_derivatives(&q, &qd, &tau).unwrap();
        let fd_of = |q: &JointVector<N>, qd: &JointVector<N>, tau: &JointVector<N>| {
            dynamic(&robot.forward_dynamics(q, qd, tau).unwrap())
        };
        record(
            "d qdd/d q",
            error(&dynamic(&fd.dqdd_dq), &central(&q, |x| fd_of(x, &qd, &tau))),
        );
        record(
            "d qdd/d qd",
            error(
                &dynamic(&fd.dqdd_dqd),
                &central(&qd, |x| fd_of(&q, x, &tau)),
            ),
        );
        record(
            "d qdd/d tau",
            error(
                &dynamic(&fd.mass_matrix_inverse),
                &central(&tau, |x| fd_of(&q, &qd, x)),
            ),
        );
        let identity = fd.mass_matrix_inverse * robot.mass_matrix(&q);
        record(
            "M^-1 M = I",
            error(&dynamic(&identity), &dynamic(&JointMatrix::<N>::identity())),
        );

        let dj = robot.jacobian_derivatives(&q);
        let column = central(&q, |x| dynamic(&robot.jacobian(x)));
        for k in 0..N {
            let dk = DMatrix::from_fn(6, N, |r, c| column[(c * 6 + r, k)]);
            record("d J/d q", error(&dynamic(&dj[k]), &dk));
        }

        // With a tool wrench: tau = ID + J^T f, qdd = FD(q, qd, tau - J^T f).
        let (idw, dtau_df) = inverse_dynamics_derivatives_with_wrench(robot, &q, &qd, &qdd, &f);
        let id_w = |q: &JointVector<N>, f: &Wrench| {
            dynamic(&(robot.inverse_dynamics(q, &qd, &qdd) + robot.jacobian(q).transpose() * f))
        };
        record(
            "wrench: d tau/d q",
            error(&dynamic(&idw.dtau_dq), &central(&q, |x| id_w(x, &f))),
        );
        record(
            "wrench: d tau/d f",
            error(&dynamic(&dtau_df), &central(&f, |x| id_w(&q, x))),
        );
        let (fdw, dqdd_df) =
            forward_dynamics_derivatives_with_wrench(robot, &q, &qd, &tau, &f).unwrap();
        let fd_w = |q: &JointVector<N>, qd: &JointVector<N>, f: &Wrench| {
            fd_of(q, qd, &(tau - robot.jacobian(q).transpose() * f))
        };
        record(
            "wrench: d qdd/d q",
            error(&dynamic(&fdw.dqdd_dq), &central(&q, |x| fd_w(x, &qd, &f))),
        );
        record(
            "wrench: d qdd/d qd",
            error(&dynamic(&fdw.dqdd_dqd), &central(&qd, |x| fd_w(&q, x, &f))),
        );
        record(
            "wrench: d qdd/d f",
            error(&dynamic(&dqdd_df), &central(&f, |x| fd_w(&q, &qd, x))),
        );
    }
    worst
}

/// `max |a - b| / max(1, max |a|)` of an `f64` output and its `f32` variant.
fn f32_error(a: &[f64], b: &[f32]) -> f64 {
    let scale = a.iter().fold(1.0f64, |s, v| s.max(v.abs()));
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - f64::from(*y)).abs())
        .fold(0.0f64, f64::max)
        / scale
}

/// Bound on the `f32` derivatives' error against `f64` (measured worst 1.2e-5, the Panda's
/// forward-dynamics derivatives).
const BOUND_F32: f64 = 1e-4;

macro_rules! robots {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        fn all_robots() -> Vec<(&'static str, Vec<(&'static str, f64)>)> {
            vec![$((stringify!($module), check_robot(&armdyn::model::$ty))),*]
        }

        /// Worst `f32` error of each derivative function per robot.
        fn all_robots_f32() -> Vec<(&'static str, [f64; 3])> {
            vec![$((stringify!($module), {
                use armdyn_generated::$module as g;
                let mut rng = Xoshiro256PlusPlus::seed_from_u64(SEED);
                let mut worst = [0.0f64; 3];
                for _ in 0..STATES {
                    let q: [f64; $n] = core::array::from_fn(|i| {
                        let [lo, hi] = g::JOINT_LIMITS[i];
                        rng.random_range(lo..=hi)
                    });
                    let qd: [f64; $n] = core::array::from_fn(|_| rng.random_range(-2.0..=2.0));
                    let qdd: [f64; $n] = core::array::from_fn(|_| rng.random_range(-5.0..=5.0));
                    let tau = g::inverse_dynamics(&q, &qd, &qdd);
                    let s = |x: &[f64; $n]| x.map(|v| v as f32);
                    let errors = [
                        f32_error(g::jacobian_derivatives(&q).as_flattened().as_flattened(),
                            g::f32::jacobian_derivatives(&s(&q)).as_flattened().as_flattened()),
                        f32_error(g::inverse_dynamics_derivatives(&q, &qd, &qdd).as_flattened(),
                            g::f32::inverse_dynamics_derivatives(&s(&q), &s(&qd), &s(&qdd)).as_flattened()),
                        f32_error(g::forward_dynamics_derivatives(&q, &qd, &tau).as_flattened(),
                            g::f32::forward_dynamics_derivatives(&s(&q), &s(&qd), &s(&tau)).as_flattened()),
                    ];
                    for (w, e) in worst.iter_mut().zip(errors) {
                        assert!(e <= BOUND_F32, "{}: f32 derivative off by {e:e}", stringify!($module));
                        *w = w.max(e);
                    }
                }
                worst
            })),*]
        }
    };
}

armdyn_generated::for_each_robot!(robots);

#[test]
fn derivatives_equal_central_differences_for_every_robot() {
    let all = all_robots();
    assert_eq!(all.len(), armdyn_generated::ROBOTS.len());
    for (robot, worst) in &all {
        for (name, e) in worst {
            println!("{robot:<10} {name:<22} {e:.3e}");
        }
    }
}

#[test]
fn f32_derivatives_stay_near_f64_for_every_robot() {
    println!(
        "{:<10} {:>12} {:>12} {:>12}",
        "robot", "dJ/dq", "dID", "dFD"
    );
    for (robot, w) in all_robots_f32() {
        println!(
            "{robot:<10} {:>12.3e} {:>12.3e} {:>12.3e}",
            w[0], w[1], w[2]
        );
    }
}
