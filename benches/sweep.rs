//! Criterion benchmarks of Monte Carlo sweeps on `scenarios/robustness.toml`: one nominal
//! run as `armdyn run scenario` does it without writing files, one trial of the sweep (its
//! draws applied: a perturbed plant through the parametric model, a noisy sensor), and 16
//! trials on 1 and on 2 threads (trials per second = 16 / the time).
//!
//! Run: `cargo bench --bench sweep`.

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use armdyn::scenario::{execute, prepare, Scenario};
use armdyn::sweep::{apply, draw_all, run_sweep, run_trial, SweepSpec, TABLE};
use criterion::{criterion_group, criterion_main, Criterion};

fn sweep(c: &mut Criterion) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/robustness.toml");
    let scenario = Scenario::load_with(&file, &[TABLE]).expect("robustness.toml");
    let spec = SweepSpec::of(&scenario).expect("checked").expect("[sweep]");
    let mut group = c.benchmark_group("robustness");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(10))
        .warm_up_time(Duration::from_secs(2));
    group.bench_function("single_run", |b| {
        b.iter(|| {
            let p = prepare(black_box(&scenario)).expect("prepare");
            execute(&scenario, p, |_| {}).expect("run")
        });
    });
    let draw = draw_all(&spec, 1, 1).remove(0);
    group.bench_function("sweep_trial", |b| {
        b.iter(|| {
            let trial = apply(black_box(&scenario), &spec, &draw).expect("the draw applies");
            run_trial(&trial, None)
        });
    });
    for threads in [1, 2] {
        group.bench_function(format!("sweep_16_trials/threads_{threads}"), |b| {
            b.iter(|| run_sweep(&scenario, &spec, 16, 1, threads, &|| {}).expect("pool"));
        });
    }
    group.finish();
}

criterion_group!(benches, sweep);
criterion_main!(benches);
