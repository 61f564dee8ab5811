//! Criterion benchmarks of every generated function of every robot (numeric and
//! parametric modules), plus forward dynamics through `RobotModel`.
//!
//! Run: `cargo bench --bench generated` (all, a few minutes), or filter, e.g.
//! `cargo bench --bench generated -- '^(scara|puma560)/(mass_matrix|coriolis|gravity)$'`.
//! Inputs go through `black_box` so nothing is constant-folded; the state is fixed and
//! generic (no zero or special angles).

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::SVector;
use scara::model::{forward_dynamics, forward_dynamics_cholesky, RobotModel};

fn state<const N: usize>() -> ([f64; N], [f64; N], [f64; N]) {
    let q = core::array::from_fn(|i| 0.3 + 0.17 * i as f64);
    let qd = core::array::from_fn(|i| 0.9 - 0.23 * i as f64);
    let qdd = core::array::from_fn(|i| -1.1 + 0.41 * i as f64);
    (q, qd, qdd)
}

macro_rules! bench_generated {
    ($c:expr, $module:ident, $n:literal) => {{
        use scara_generated::$module as g;
        let (q, qd, qdd) = state::<$n>();
        let params = g::standard_parameters();
        let mut group = $c.benchmark_group(stringify!($module));
        group.bench_function("frame_poses", |b| b.iter(|| g::frame_poses(black_box(&q))));
        group.bench_function("end_effector_pose", |b| {
            b.iter(|| g::end_effector_pose(black_box(&q)))
        });
        group.bench_function("jacobian", |b| b.iter(|| g::jacobian(black_box(&q))));
        group.bench_function("jdot_qd", |b| {
            b.iter(|| g::jdot_qd(black_box(&q), black_box(&qd)))
        });
        group.bench_function("mass_matrix", |b| b.iter(|| g::mass_matrix(black_box(&q))));
        group.bench_function("coriolis_matrix", |b| {
            b.iter(|| g::coriolis_matrix(black_box(&q), black_box(&qd)))
        });
        group.bench_function("coriolis", |b| {
            b.iter(|| g::coriolis(black_box(&q), black_box(&qd)))
        });
        group.bench_function("gravity", |b| b.iter(|| g::gravity(black_box(&q))));
        group.bench_function("inverse_dynamics", |b| {
            b.iter(|| g::inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)))
        });
        group.bench_function("forward_dynamics", |b| {
            b.iter(|| g::forward_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)))
        });
        group.bench_function("mass_matrix_and_bias", |b| {
            b.iter(|| g::mass_matrix_and_bias(black_box(&q), black_box(&qd)))
        });
        group.bench_function("regressor", |b| {
            b.iter(|| g::regressor(black_box(&q), black_box(&qd), black_box(&qdd)))
        });
        group.bench_function("standard_parameters", |b| b.iter(g::standard_parameters));
        group.bench_function("parametric/mass_matrix", |b| {
            b.iter(|| g::parametric::mass_matrix(black_box(&q), black_box(&params)))
        });
        group.bench_function("parametric/coriolis_matrix", |b| {
            b.iter(|| {
                g::parametric::coriolis_matrix(black_box(&q), black_box(&qd), black_box(&params))
            })
        });
        group.bench_function("parametric/coriolis", |b| {
            b.iter(|| g::parametric::coriolis(black_box(&q), black_box(&qd), black_box(&params)))
        });
        group.bench_function("parametric/gravity", |b| {
            b.iter(|| g::parametric::gravity(black_box(&q), black_box(&params)))
        });
        group.bench_function("parametric/inverse_dynamics", |b| {
            b.iter(|| {
                g::parametric::inverse_dynamics(
                    black_box(&q),
                    black_box(&qd),
                    black_box(&qdd),
                    black_box(&params),
                )
            })
        });
        // qdd doubles as the torque input of forward dynamics.
        group.bench_function("parametric/forward_dynamics", |b| {
            b.iter(|| {
                g::parametric::forward_dynamics(
                    black_box(&q),
                    black_box(&qd),
                    black_box(&qdd),
                    black_box(&params),
                )
            })
        });
        group.finish();
    }};
}

fn bench_forward_dynamics<const N: usize, R: RobotModel<N>>(c: &mut Criterion, robot: R) {
    let (q, qd, _) = state::<N>();
    let (q, qd) = (SVector::<f64, N>::from(q), SVector::<f64, N>::from(qd));
    let tau = robot.gravity(&q) + SVector::<f64, N>::from_element(1.0);
    let zero = SVector::<f64, N>::zeros();
    let mut group = c.benchmark_group(R::NAME);
    group.bench_function("model/forward_dynamics", |b| {
        b.iter(|| {
            forward_dynamics(
                &robot,
                black_box(&q),
                black_box(&qd),
                black_box(&tau),
                black_box(&zero),
            )
        })
    });
    group.bench_function("model/forward_dynamics_cholesky", |b| {
        b.iter(|| {
            forward_dynamics_cholesky(
                &robot,
                black_box(&q),
                black_box(&qd),
                black_box(&tau),
                black_box(&zero),
            )
        })
    });
    group.finish();
}

// Every robot of the generated registry.
macro_rules! bench_every_robot {
    ([$c:ident] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        $( bench_generated!($c, $module, $n); )*
        $( bench_forward_dynamics($c, scara::model::$ty); )*
    };
}

fn generated(c: &mut Criterion) {
    scara_generated::for_each_robot!(bench_every_robot, c);
}

fn config() -> Criterion {
    // Short runs: the functions take nanoseconds, and the machine is shared.
    Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

criterion_group! {
    name = benches;
    config = config();
    targets = generated
}
criterion_main!(benches);
