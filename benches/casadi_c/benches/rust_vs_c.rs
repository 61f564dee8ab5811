//! ns per call of every generated Rust function of `scara` and `puma560` (numeric and
//! parametric) and of CasADi's generated C for the same graph, in the same run, on the same
//! inputs (through `black_box`). Groups are `<robot>/<function>` and
//! `<robot>/parametric/<function>`, each with a `rust` and a `casadi_c` benchmark.
//!
//! The Rust functions are `#[inline]` and are called directly (inlined into the loop); the C
//! goes through [`CFunction::call`] (size checks, pointer set-up, an opaque call; for the
//! sparse regressor output also the scatter into the dense output), which is how Rust code
//! would use it.
//!
//! Run: `cargo bench -p armdyn-casadi-c-bench --bench rust_vs_c`, then
//! `cargo run -p armdyn-casadi-c-bench --bin bench_table --release` for the table.
//! Warm-up 1 s and measurement 2 s per benchmark unless given on the command line.

use std::hint::black_box;
use std::time::Duration;

use armdyn_casadi_c_bench::CFunction;
use criterion::measurement::WallTime;
use criterion::{criterion_group, criterion_main, BenchmarkGroup, Criterion};

/// A fixed, generic state (no zeros, no special angles), as in the root crate's benchmarks.
fn state<const N: usize>() -> ([f64; N], [f64; N], [f64; N]) {
    let q = core::array::from_fn(|i| 0.3 + 0.17 * i as f64);
    let qd = core::array::from_fn(|i| 0.9 - 0.23 * i as f64);
    let qdd = core::array::from_fn(|i| -0.4 + 0.31 * i as f64);
    (q, qd, qdd)
}

fn bench_c(group: &mut BenchmarkGroup<'_, WallTime>, name: &str, inputs: &[&[f64]]) {
    let mut f = CFunction::new(name).unwrap_or_else(|e| panic!("{e}"));
    let mut out = vec![0.0; f.output_len()];
    group.bench_function("casadi_c", |b| {
        b.iter(|| f.call(black_box(inputs), black_box(&mut out[..])).unwrap());
    });
}

/// One group: the Rust function `$rust` and the C function `<robot>_<$c>` on the same inputs.
macro_rules! pair {
    ($crit:expr, $robot:ident, $function:literal, $c:literal, $rust:path, [$($arg:ident),*]) => {{
        let mut group = $crit.benchmark_group(concat!(stringify!($robot), "/", $function));
        group.bench_function("rust", |b| b.iter(|| $rust($(black_box(&$arg)),*)));
        bench_c(&mut group, concat!(stringify!($robot), "_", $c), &[$(&$arg[..]),*]);
        group.finish();
    }};
}

macro_rules! bench_robot {
    ($crit:expr, $robot:ident) => {{
        use armdyn_generated::$robot as g;
        use armdyn_generated::$robot::parametric as p;
        let (q, qd, qdd) = state::<{ g::DOF }>();
        let params = g::standard_parameters();
        // The torques of (q, qd, qdd), so forward dynamics gives qdd back.
        let tau = g::inverse_dynamics(&q, &qd, &qdd);
        let c = $crit;
        pair!(c, $robot, "frame_poses", "frame_poses", g::frame_poses, [q]);
        pair!(
            c,
            $robot,
            "end_effector_pose",
            "end_effector_pose",
            g::end_effector_pose,
            [q]
        );
        pair!(c, $robot, "jacobian", "jacobian", g::jacobian, [q]);
        pair!(
            c,
            $robot,
            "jacobian_and_position",
            "jacobian_and_position",
            g::jacobian_and_position,
            [q]
        );
        pair!(c, $robot, "jdot_qd", "jdot_qd", g::jdot_qd, [q, qd]);
        pair!(c, $robot, "mass_matrix", "mass_matrix", g::mass_matrix, [q]);
        pair!(
            c,
            $robot,
            "coriolis_matrix",
            "coriolis_matrix",
            g::coriolis_matrix,
            [q, qd]
        );
        pair!(c, $robot, "coriolis", "coriolis", g::coriolis, [q, qd]);
        pair!(c, $robot, "gravity", "gravity", g::gravity, [q]);
        pair!(
            c,
            $robot,
            "inverse_dynamics",
            "inverse_dynamics",
            g::inverse_dynamics,
            [q, qd, qdd]
        );
        pair!(
            c,
            $robot,
            "forward_dynamics",
            "forward_dynamics",
            g::forward_dynamics,
            [q, qd, tau]
        );
        pair!(
            c,
            $robot,
            "mass_matrix_and_bias",
            "mass_matrix_and_bias",
            g::mass_matrix_and_bias,
            [q, qd]
        );
        pair!(
            c,
            $robot,
            "regressor",
            "regressor",
            g::regressor,
            [q, qd, qdd]
        );
        pair!(
            c,
            $robot,
            "standard_parameters",
            "standard_parameters",
            g::standard_parameters,
            []
        );
        pair!(
            c,
            $robot,
            "parametric/mass_matrix",
            "parametric_mass_matrix",
            p::mass_matrix,
            [q, params]
        );
        pair!(
            c,
            $robot,
            "parametric/coriolis_matrix",
            "parametric_coriolis_matrix",
            p::coriolis_matrix,
            [q, qd, params]
        );
        pair!(
            c,
            $robot,
            "parametric/coriolis",
            "parametric_coriolis",
            p::coriolis,
            [q, qd, params]
        );
        pair!(
            c,
            $robot,
            "parametric/gravity",
            "parametric_gravity",
            p::gravity,
            [q, params]
        );
        pair!(
            c,
            $robot,
            "parametric/inverse_dynamics",
            "parametric_inverse_dynamics",
            p::inverse_dynamics,
            [q, qd, qdd, params]
        );
        pair!(
            c,
            $robot,
            "parametric/forward_dynamics",
            "parametric_forward_dynamics",
            p::forward_dynamics,
            [q, qd, tau, params]
        );
    }};
}

fn rust_vs_c(c: &mut Criterion) {
    bench_robot!(&mut *c, scara);
    bench_robot!(&mut *c, puma560);
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2));
    targets = rust_vs_c
}
criterion_main!(benches);
