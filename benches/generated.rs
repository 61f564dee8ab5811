//! Criterion benchmarks of every generated function of every robot (numeric and
//! parametric modules), forward dynamics through `RobotModel`, and the lane functions
//! (`<robot>::lanes` over `f64x2` and `f64x4`) against the scalar ones per state (group
//! `<robot>-batch`, with criterion's throughput in states per second: the ratio is the
//! batching gain; build with `RUSTFLAGS="-C target-cpu=native"` for AVX's `f64x4`).
//!
//! Run: `cargo bench --bench generated` (all, a few minutes), or filter, e.g.
//! `cargo bench --bench generated -- '^(scara|puma560)/(mass_matrix|coriolis|gravity)$'`.
//! Inputs go through `black_box` so nothing is constant-folded; the state is fixed and
//! generic (no zero or special angles).

use std::hint::black_box;
use std::time::Duration;

use armdyn::model::{forward_dynamics, forward_dynamics_cholesky, RobotModel};
use armdyn_generated::lanes::Lane;
use armdyn_generated::wide::{f64x2, f64x4};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use nalgebra::SVector;

fn state<const N: usize>() -> ([f64; N], [f64; N], [f64; N]) {
    let q = core::array::from_fn(|i| 0.3 + 0.17 * i as f64);
    let qd = core::array::from_fn(|i| 0.9 - 0.23 * i as f64);
    let qdd = core::array::from_fn(|i| -1.1 + 0.41 * i as f64);
    (q, qd, qdd)
}

macro_rules! bench_generated {
    ($c:expr, $module:ident, $n:literal) => {{
        use armdyn_generated::$module as g;
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

/// Distinct states in lanes: lane `k` is [`state`] with every entry offset by `0.05 k`.
fn lanes<L: Lane, const N: usize>(x: &[f64; N]) -> [L; N] {
    core::array::from_fn(|i| L::from_fn(|k| x[i] + 0.05 * k as f64))
}

macro_rules! bench_lanes {
    ($group:ident, $g:ident, $lane:ty, $name:literal, $q:ident, $qd:ident, $qdd:ident, $tau:ident) => {{
        let (q, qd, qdd, tau): ([$lane; _], [$lane; _], [$lane; _], [$lane; _]) =
            (lanes(&$q), lanes(&$qd), lanes(&$qdd), lanes(&$tau));
        $group.throughput(Throughput::Elements(<$lane as Lane>::LANES as u64));
        $group.bench_function(concat!($name, "/mass_matrix_and_bias"), |b| {
            b.iter(|| $g::lanes::mass_matrix_and_bias(black_box(&q), black_box(&qd)))
        });
        $group.bench_function(concat!($name, "/forward_dynamics"), |b| {
            b.iter(|| $g::lanes::forward_dynamics(black_box(&q), black_box(&qd), black_box(&tau)))
        });
        $group.bench_function(concat!($name, "/inverse_dynamics"), |b| {
            b.iter(|| $g::lanes::inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)))
        });
    }};
}

macro_rules! bench_batch {
    ($c:expr, $module:ident, $n:literal) => {{
        use armdyn_generated::$module as g;
        let (q, qd, qdd) = state::<$n>();
        let tau = g::inverse_dynamics(&q, &qd, &qdd);
        let mut group = $c.benchmark_group(concat!(stringify!($module), "-batch"));
        group.throughput(Throughput::Elements(1));
        group.bench_function("scalar/mass_matrix_and_bias", |b| {
            b.iter(|| g::mass_matrix_and_bias(black_box(&q), black_box(&qd)))
        });
        group.bench_function("scalar/forward_dynamics", |b| {
            b.iter(|| g::forward_dynamics(black_box(&q), black_box(&qd), black_box(&tau)))
        });
        group.bench_function("scalar/inverse_dynamics", |b| {
            b.iter(|| g::inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)))
        });
        bench_lanes!(group, g, f64x2, "f64x2", q, qd, qdd, tau);
        bench_lanes!(group, g, f64x4, "f64x4", q, qd, qdd, tau);
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
        $( bench_forward_dynamics($c, armdyn::model::$ty); )*
        $( bench_batch!($c, $module, $n); )*
    };
}

/// The slice API (`armdyn::model::batch`, lanes of `lanes::Batch`) against a loop of scalar
/// calls, over 1024 Panda states.
fn bench_slices(c: &mut Criterion) {
    use armdyn::model::batch::{forward_dynamics_batch, mass_matrix_and_bias_batch};
    use armdyn::model::Panda;
    const STATES: usize = 1024;
    let q: Vec<[f64; 7]> = (0..STATES)
        .map(|k| core::array::from_fn(|i| 0.3 + 0.17 * i as f64 + 1e-3 * k as f64))
        .collect();
    let qd: Vec<[f64; 7]> = (0..STATES).map(|k| [0.5 - 1e-3 * k as f64; 7]).collect();
    let tau: Vec<[f64; 7]> = (0..STATES).map(|k| [1.0 + 1e-3 * k as f64; 7]).collect();
    let (mut out, mut mass, mut bias) = (
        vec![[0.0; 7]; STATES],
        vec![[[0.0; 7]; 7]; STATES],
        vec![[0.0; 7]; STATES],
    );
    let mut group = c.benchmark_group("panda-slice");
    group.throughput(Throughput::Elements(STATES as u64));
    group.bench_function("loop/forward_dynamics", |b| {
        b.iter(|| {
            for k in 0..STATES {
                out[k] = armdyn_generated::panda::forward_dynamics(&q[k], &qd[k], &tau[k]);
            }
            black_box(&out);
        })
    });
    group.bench_function("batch/forward_dynamics", |b| {
        b.iter(|| forward_dynamics_batch(&Panda, black_box(&q), &qd, &tau, &mut out))
    });
    group.bench_function("loop/mass_matrix_and_bias", |b| {
        b.iter(|| {
            for k in 0..STATES {
                let rows = armdyn_generated::panda::mass_matrix_and_bias(&q[k], &qd[k]);
                for i in 0..7 {
                    mass[k][i].copy_from_slice(&rows[i][..7]);
                    bias[k][i] = rows[i][7];
                }
            }
            black_box((&mass, &bias));
        })
    });
    group.bench_function("batch/mass_matrix_and_bias", |b| {
        b.iter(|| mass_matrix_and_bias_batch(&Panda, black_box(&q), &qd, &mut mass, &mut bias))
    });
    group.finish();
}

fn generated(c: &mut Criterion) {
    armdyn_generated::for_each_robot!(bench_every_robot, c);
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
    targets = generated, bench_slices
}
criterion_main!(benches);
