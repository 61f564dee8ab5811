//! The stepped controller (`armdyn::scenario::SteppedController`) is the simulator's: driven
//! with a run's own samples (time, joints, the true contact wrench), it gives the run's
//! torques bit for bit, before and after saturation, with the same force mode and sensor
//! reading, for every shipped scenario file (every kind: position, hybrid, impedance and
//! admittance laws, six-dimensional tasks, tools behind the sensor, supervised runs with
//! injected faults, deployable `f32` steps excepted) and a reset at another time origin.

use std::path::{Path, PathBuf};

use armdyn::model::JointVector;
use armdyn::scenario::{prepare_for, Mode, Scenario, ScenarioRobot, SteppedController};

fn files() -> Vec<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let mut out = Vec::new();
    for dir in [
        root.clone(),
        root.join("faults"),
        root.join("joint-reference"),
    ] {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.extension().is_some_and(|x| x == "toml") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// Runs `scenario`, then drives a fresh stepped controller with the run's samples; returns
/// (samples compared, samples in force control, samples after a trip).
fn compare_on<const N: usize, R: ScenarioRobot<N>>(
    s: &Scenario,
    robot: &R,
    t0: f64,
) -> (usize, usize, usize) {
    let mut run = prepare_for(s, *robot).unwrap_or_else(|e| panic!("{e}"));
    let out = run
        .run(|_| {})
        .unwrap_or_else(|e| panic!("{}: {e}", s.file));
    let mut c = SteppedController::new(s, *robot).unwrap();
    let first = &out.samples[0];
    c.reset(t0, &first.q, &first.qd);
    let (mut forced, mut tripped) = (0, 0);
    for (k, x) in out.samples.iter().enumerate() {
        let tau = c.step(x.t + t0, &x.q, &x.qd, &x.wrench);
        let r = c.report();
        // At the run's own time origin bit for bit; at another, `(t + t0) - t0` is `t`
        // to an ulp of `t0`, so the setpoints move by that much.
        let exact = t0 == 0.0;
        let same = |a: &JointVector<N>, b: &JointVector<N>| {
            a.iter().zip(b.iter()).all(|(u, v)| {
                if exact {
                    u.to_bits() == v.to_bits()
                } else {
                    (u - v).abs() <= 1e-7 * (1.0 + v.abs())
                }
            })
        };
        assert!(
            same(&tau, &x.tau) && same(&r.command, &x.tau_command),
            "{}: sample {k} (t = {}): stepped {tau:?} / {:?}, simulated {:?} / {:?}",
            s.file,
            x.t,
            r.command,
            x.tau,
            x.tau_command
        );
        assert_eq!(
            r.detail.force_controlled, x.force_controlled,
            "{}: sample {k}",
            s.file
        );
        let measured = r.detail.measured_wrench.unwrap_or(x.wrench);
        assert!(
            !exact
                || measured
                    .iter()
                    .zip(x.measured_wrench.iter())
                    .all(|(a, b)| a.to_bits() == b.to_bits()),
            "{}: sample {k}: measured wrench",
            s.file
        );
        forced += usize::from(r.mode == Mode::Force);
        tripped += usize::from(r.mode == Mode::Tripped);
        if exact {
            for i in 0..N {
                assert_eq!(r.saturated[i], x.tau[i] != x.tau_command[i]);
            }
        }
    }
    (out.samples.len(), forced, tripped)
}

fn compare(path: &Path, t0: f64) -> Option<(usize, usize, usize)> {
    // Sweep files and files that ask for another tool's tables are not runs.
    let s = Scenario::load(path).ok()?;
    // The deployable f32 steps are checked bit for bit against their own reference elsewhere
    // (tests/scara/deploy_hybrid.rs); here the reference controllers.
    Some(
        armdyn::with_robot_named!(s.robot.as_str(), |robot: R, N, _module| {
            compare_on(&s, &robot, t0)
        })
        .unwrap_or_else(|| panic!("{}: unknown robot", s.file)),
    )
}

#[test]
fn the_stepped_controller_gives_the_simulators_torques_bit_for_bit() {
    let (mut runs, mut samples, mut forced, mut tripped) = (0, 0, 0, 0);
    for path in files() {
        let Some((n, f, t)) = compare(&path, 0.0) else {
            continue;
        };
        runs += 1;
        samples += n;
        forced += f;
        tripped += t;
    }
    println!(
        "{runs} scenario files, {samples} samples bit for bit ({forced} in force control, {tripped} after a trip)"
    );
    assert!(runs >= 30, "only {runs} scenario files ran");
    assert!(forced > 10_000 && tripped > 100, "{forced} {tripped}");
}

#[test]
fn a_reset_at_another_time_shifts_the_reference_and_nothing_else() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    for file in ["thesis-hybrid.toml", "panda-wipe.toml"] {
        let (n, forced, _) = compare(&root.join(file), 1024.0).unwrap();
        assert!(n > 1000 && forced > 1000, "{file}: {n} {forced}");
    }
}

/// A recorded stepped run (`record`, then `outcome`) has the simulated run's metrics.
fn recorded<const N: usize, R: ScenarioRobot<N>>(
    s: &Scenario,
    robot: &R,
) -> (serde_json::Value, serde_json::Value) {
    let simulated = prepare_for(s, *robot).unwrap().execute(s, |_| {}).unwrap();
    let mut run = prepare_for(s, *robot).unwrap();
    let out = run.run(|_| {}).unwrap();
    let mut c = SteppedController::new(s, *robot).unwrap();
    c.record();
    c.reset(0.0, &out.samples[0].q, &out.samples[0].qd);
    for x in &out.samples {
        c.step(x.t, &x.q, &x.qd, &x.wrench);
    }
    let stepped = c.outcome(s).expect("steps were recorded");
    (
        armdyn::scenario::metrics_json(s, &simulated.outcome),
        armdyn::scenario::metrics_json(s, &stepped.outcome),
    )
}

#[test]
fn a_recorded_stepped_run_has_the_simulated_runs_metrics() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    for file in [
        "thesis-hybrid.toml",
        "panda-wipe.toml",
        "faults/panda-nan.toml",
    ] {
        let s = Scenario::load(&root.join(file)).unwrap();
        let (simulated, stepped) =
            armdyn::with_robot_named!(s.robot.as_str(), |robot: R, N, _module| {
                recorded(&s, &robot)
            })
            .unwrap();
        assert_eq!(simulated, stepped, "{file}");
    }
}
