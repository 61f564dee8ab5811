//! The deployable hybrid step (`armdyn::robots::scara::deploy`):
//!
//! - in `f64` it is the law of `HybridForcePosition` in the thesis configuration (the one
//!   `embedded/src/cases.rs::hybrid()` builds): equal to the last bit over many random
//!   states and steps across the switch, near singularities (the damped solve) included,
//!   since both run the same operations in the same order (`JacobianFactor` for the solve);
//! - in `f32`, driving the `f64` plant through the thesis's hybrid trial
//!   (`scenarios/thesis-hybrid.toml`), it still meets the hybrid bar: normal-force overshoot
//!   <= 5 %, settling <= 0.1 s, RMS force error over the last 5 s <= 2 N.
//!
//! `cargo test --release --test scara deploy_hybrid -- --nocapture` prints the largest difference
//! and both trials' metrics.

#[path = "../../embedded/src/cases.rs"]
#[allow(dead_code)]
mod cases;

use std::path::Path;

use armdyn::control::hybrid::JacobianSolve;
use armdyn::control::{Controller, ControllerInput};
use armdyn::metrics::ForceSummary;
use armdyn::model::{RobotModel, Scara, Wrench};
use armdyn::robots::scara::deploy::{Deployed, ScaraHybrid};
use armdyn::scenario::{
    execute, prepare_deployed, prepare_deployed_for, prepare_for, ForceController,
    PositionController, Precision, Recorded, Scenario,
};
use armdyn::target::CartesianTarget;
use armdyn::target::JointTarget;
use nalgebra::{Vector3, Vector4};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// Runs of the comparison, and steps per run (every run crosses the switch at 2 s).
const RUNS: usize = 200;
const STEPS: usize = 40;

fn random_input(rng: &mut Xoshiro256PlusPlus, near_singular: bool) -> [Vector4<f64>; 5] {
    let limits = Scara
        .lower_limits()
        .zip_map(&Scara.upper_limits(), |a, b| (a, b));
    let mut q = limits.map(|(lo, hi)| rng.random_range(lo..=hi));
    if near_singular {
        // Arm stretched out: q2 within 1e-4 rad of 0, where J_r's determinant vanishes and
        // the solve is damped.
        q[1] = rng.random_range(-1e-4..=1e-4);
    }
    let qd = Vector4::from_fn(|_, _| rng.random_range(-1.0..=1.0));
    let q_ref = q + Vector4::from_fn(|_, _| rng.random_range(-0.02..=0.02));
    let qd_ref = qd + Vector4::from_fn(|_, _| rng.random_range(-0.1..=0.1));
    let other = Vector4::new(
        rng.random_range(0.2..=0.6),
        rng.random_range(-0.4..=0.4),
        rng.random_range(0.1..=0.2),
        rng.random_range(-250.0..=0.0),
    );
    [q, qd, q_ref, qd_ref, other]
}

#[test]
fn f64_instantiation_is_the_hybrid_law_of_the_thesis_configuration() {
    let mut reference = cases::hybrid().expect("the thesis controller");
    let mut deployed = Deployed::new(ScaraHybrid::<f64>::thesis().expect("the design"));
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(0xDE9_2026);
    let dt = 1e-3;
    let (mut compared, mut forced, mut damped) = (0usize, 0usize, 0usize);
    for run in 0..RUNS {
        reference.reset();
        deployed.reset();
        for k in 0..STEPS {
            let [q, qd, q_ref, qd_ref, other] = random_input(&mut rng, run % 10 == 0);
            let target = JointTarget {
                q: q_ref,
                qd: qd_ref,
                qdd: Vector4::zeros(),
            };
            let cartesian = CartesianTarget {
                velocity: Vector3::new(0.0, 0.1, 0.0),
                ..CartesianTarget::at_rest(
                    Vector3::new(other[0], other[1], other[2]),
                    armdyn::target::orientation::from_yaw(0.0),
                )
            };
            let wrench = Wrench::new(1.0, -2.0, other[3], 0.0, 0.0, 0.1);
            let wrench_ref = Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0);
            let input = ControllerInput {
                t: 1.98 + k as f64 * dt,
                q: &q,
                qd: &qd,
                target: &target,
                cartesian: &cartesian,
                wrench: &wrench,
                wrench_ref: &wrench_ref,
                wrench_age_s: 0.0,
            };
            let a = reference.step(&input, dt);
            let b = deployed.step(&input, dt);
            assert_eq!(
                reference.report().force_controlled,
                deployed.report().force_controlled
            );
            forced += usize::from(deployed.report().force_controlled);
            damped += usize::from(reference.last_solve() == JacobianSolve::Damped);
            assert_eq!(a, b, "run {run} step {k}: not the same to the last bit");
            compared += 1;
        }
    }
    assert!(forced >= compared / 3 && forced < compared);
    assert!(damped > 0);
    println!(
        "{compared} steps ({forced} force-controlled, {damped} of them damped): all equal to \
         the last bit"
    );
}

/// The `f32` step against the `f64` one at the firmware's six cases (`embedded/src/cases.rs`,
/// the inputs rounded to `f32`), stepped in case order as the firmware does: the torque
/// differs by at most `F32_STEP` relative to the max norm of the `f64` torque (measured:
/// 1.4e-7).
const F32_STEP: f64 = 2e-6;

#[test]
fn f32_step_is_close_to_the_f64_step_at_the_firmware_cases() {
    let mut double = Deployed::new(ScaraHybrid::<f64>::thesis().expect("the design"));
    let mut single = ScaraHybrid::<f32>::thesis().expect("the design");
    let mut worst = 0.0f64;
    for k in 0..cases::CASES {
        let a = cases::with_step_input(k, |input| double.step(input, cases::CONTROL_DT));
        let b = single.step(&cases::step_input_f32(k), cases::CONTROL_DT as f32);
        let b = Vector4::from(b.map(f64::from));
        let diff = (a - b).amax() / a.amax().max(1.0);
        assert!(diff <= F32_STEP, "case {k}: {a} vs {b} ({diff:e})");
        worst = worst.max(diff);
    }
    assert!(worst > 0.0);
    println!("f32 step against f64 at the firmware cases: largest relative difference {worst:e}");
}

fn thesis_hybrid(deployed: Option<Box<dyn Controller<4>>>) -> (String, ForceSummary) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/thesis-hybrid.toml");
    let scenario = Scenario::load(&path).expect("the thesis scenario");
    let mut prepared = prepare_for(&scenario, Scara).expect("prepares");
    if let Some(controller) = deployed {
        prepared.controller = controller;
    }
    let outcome = prepared.execute(&scenario, |_| {}).expect("runs").outcome;
    (
        outcome.controller_name.to_string(),
        outcome.force.expect("force metrics"),
    )
}

#[test]
fn f32_controller_meets_the_hybrid_bar_on_the_thesis_trial() {
    let (name64, f64_metrics) = thesis_hybrid(None);
    let single = Deployed::new(ScaraHybrid::<f32>::thesis().expect("the design"));
    let (name32, f32_metrics) = thesis_hybrid(Some(Box::new(single)));
    for (name, m) in [(name64, &f64_metrics), (name32, &f32_metrics)] {
        println!(
            "{name:<20} overshoot {:.6} %  settling {:?} s  RMS last 5 s {:.6} N  x-y RMS {:.6} mm",
            m.force_overshoot_pct,
            m.settling_time_s,
            m.force_rms_error_last_n,
            m.xy_rms_error_contact_mm
        );
    }
    let s = f32_metrics;
    assert!(s.force_overshoot_pct <= 5.0, "{s:?}");
    assert!(s.settling_time_s.is_some_and(|t| t <= 0.1), "{s:?}");
    assert!(s.force_rms_error_last_n <= 2.0, "{s:?}");
    // The f32 run is its own: single-precision rounding changes the numbers.
    assert_ne!(s, f64_metrics);
}

fn scenario(name: &str) -> Scenario {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios")
        .join(name);
    Scenario::load(&path).expect("a shipped scenario")
}

#[test]
fn a_scenario_run_by_the_deployable_f64_step_is_the_reference_run() {
    // Same operations in the same order: every sample of the 10 s thesis trial identical.
    let s = scenario("thesis-hybrid.toml");
    let reference = prepare_for(&s, Scara).unwrap().execute(&s, |_| {}).unwrap();
    let deployed = prepare_deployed_for(&s, Scara, Precision::F64)
        .unwrap()
        .execute(&s, |_| {})
        .unwrap();
    assert_eq!(deployed.outcome.controller_name, "hybrid-pi-ff-vd-f64");
    let (a, b) = (&reference.samples, &deployed.samples);
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert_eq!(
            (x.q, x.tau_command),
            (y.q, y.tau_command),
            "at t = {} s",
            x.t
        );
    }
    // In f32, another run that still meets the hybrid bar; its name says so.
    let single = execute(&s, prepare_deployed(&s, Precision::F32).unwrap(), |_| {}).unwrap();
    assert_eq!(single.controller_name, "hybrid-pi-ff-vd-f32");
    let m = single.force.unwrap();
    assert!(
        m.force_overshoot_pct <= 5.0 && m.force_rms_error_last_n <= 2.0,
        "{m:?}"
    );
}

#[test]
fn scenarios_the_deployable_step_cannot_run_are_refused_naming_the_key() {
    let refused = |s: &Scenario, key: &str| {
        let e = prepare_deployed(s, Precision::F32)
            .err()
            .expect("refused")
            .to_string();
        assert!(e.contains(&format!("`{key}`")), "{e}");
        assert!(e.contains("deployable step"), "{e}");
    };
    refused(&scenario("sphere-patch.toml"), "surfaces[0]");
    refused(&scenario("unknown-height.toml"), "selection");
    refused(&scenario("stiffness-1k.toml"), "force.anti_windup");
    refused(&scenario("thesis-position.toml"), "force");
    let mut s = scenario("thesis-hybrid.toml");
    s.position = PositionController::ComputedTorque;
    refused(&s, "position.law");
    let mut s = scenario("thesis-hybrid.toml");
    s.force.as_mut().unwrap().law = ForceController::Admittance;
    refused(&s, "force.law");
    let mut s = scenario("thesis-hybrid.toml");
    s.force.as_mut().unwrap().friction_feedforward = 0.1;
    refused(&s, "force.friction_feedforward");
    // The thesis's other hybrid file and the plain PI + FF law run.
    assert!(prepare_deployed(&scenario("thesis-hybrid-variable.toml"), Precision::F32).is_ok());
    let mut s = scenario("thesis-hybrid.toml");
    s.force.as_mut().unwrap().law = ForceController::PiFf;
    s.force.as_mut().unwrap().gains.2 = 0.0;
    let p = prepare_deployed(&s, Precision::F32).unwrap();
    assert_eq!(p.controller_name(), "hybrid-pi-ff-f32");
}

#[test]
fn a_deployed_run_is_prepared_stage_by_stage_once() {
    // The step replaces the laws' controller; the sensor stage runs once, so its note is the
    // reference run's with the step named after it.
    let mut s = scenario("thesis-hybrid.toml");
    s.sensor.noise_n = 5.0;
    let reference = armdyn::scenario::prepare(&s).unwrap();
    let deployed = prepare_deployed(&s, Precision::F32).unwrap();
    assert_eq!(
        deployed.gains.note,
        format!(
            "{}; run by the robot's deployable step in f32",
            reference.gains.note
        )
    );
    assert_eq!(deployed.gains.note.matches("force sensor").count(), 1);
}

#[test]
fn under_faults_the_deployable_step_runs_its_own_supervisor_in_its_precision() {
    // Fault files of the SCARA, made deployable (no anti-windup, no gravity term): in f64 the
    // step inside its own supervisor is the reference run inside the host's (every sample
    // identical, the same trips); in f32 the same cause trips in the same period.
    for file in [
        "faults/scara-nan.toml",
        "faults/scara-dropout.toml",
        "faults/scara-frozen.toml",
        "faults/scara-surface-ends.toml",
        "faults/scara-spike-unfiltered.toml",
    ] {
        let mut s = scenario(file);
        let f = s.force.as_mut().unwrap();
        f.anti_windup = false;
        f.gravity_compensation = false;
        let Recorded {
            outcome: reference,
            samples: a,
        } = prepare_for(&s, Scara).unwrap().execute(&s, |_| {}).unwrap();
        let Recorded {
            outcome: double,
            samples: b,
        } = prepare_deployed_for(&s, Scara, Precision::F64)
            .unwrap()
            .execute(&s, |_| {})
            .unwrap();
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            assert_eq!(x.tau_command, y.tau_command, "{file} at t = {} s", x.t);
        }
        let trips = |o: &armdyn::scenario::Outcome| {
            o.safety
                .trips
                .iter()
                .map(|t| (t.cause, (t.t_s * 1e3).round() as i64, t.reaction))
                .collect::<Vec<_>>()
        };
        assert!(!reference.safety.trips.is_empty(), "{file}: no trip");
        assert_eq!(trips(&reference), trips(&double), "{file}");
        assert_eq!(double.safety.nan_torque_samples, 0);
        let single = execute(&s, prepare_deployed(&s, Precision::F32).unwrap(), |_| {}).unwrap();
        assert_eq!(
            trips(&single)[0],
            trips(&reference)[0],
            "{file}: f32 {:?}",
            single.safety.trips
        );
        assert_eq!(single.safety.nan_torque_samples, 0);
    }
    // Unsupervised, the step runs bare: the NaN reading becomes a NaN torque, on which the
    // simulation stops.
    let mut s = scenario("faults/scara-nan.toml");
    let f = s.force.as_mut().unwrap();
    f.anti_windup = false;
    f.gravity_compensation = false;
    s.safety.enabled = false;
    let bare = execute(&s, prepare_deployed(&s, Precision::F32).unwrap(), |_| {});
    assert!(
        bare.as_ref()
            .is_err_and(|e| e.to_string().contains("finite")),
        "{:?}",
        bare.map(|o| o.safety.trips)
    );
}
