//! Monte Carlo sweeps: reproducible whatever the thread count, failures classified, bad
//! `[sweep]` tables refused by key.

use std::path::Path;

use armdyn::scenario::Scenario;
use armdyn::sweep::output::{failures, FailureSummary};
use armdyn::sweep::{
    run_sweep, summary_json, trials_csv, Draw, Failure, SweepRun, SweepSpec, TrialResult, TABLE,
};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn robustness() -> Scenario {
    Scenario::load_with(&root().join("scenarios/robustness.toml"), &[TABLE]).unwrap()
}

#[test]
fn same_seed_same_trials_whatever_the_threads() {
    let s = robustness();
    let spec = SweepSpec::of(&s).unwrap().unwrap();
    let one = run_sweep(&s, &spec, 6, 11, 1, &|| {}).unwrap();
    let two = run_sweep(&s, &spec, 6, 11, 2, &|| {}).unwrap();
    let a = trials_csv(&spec, &one).unwrap();
    assert_eq!(a, trials_csv(&spec, &two).unwrap());
    let other = run_sweep(&s, &spec, 6, 12, 2, &|| {}).unwrap();
    assert_ne!(a, trials_csv(&spec, &other).unwrap());
    // Draws within their ranges; one row per trial plus the header.
    assert_eq!(a.lines().count(), 7);
    for d in &one.draws {
        assert!(d.values[..4].iter().all(|m| (0.8..=1.2).contains(m)));
        assert!((0.0..=2.0).contains(&d.values[4]));
    }
    let summary = summary_json(&s, &spec, &one, 11);
    let m = &summary["metrics"]["normal_force_rms_error_last5s_n"];
    let (p5, p50, p95, max) = (
        m["p5"].as_f64().unwrap(),
        m["p50"].as_f64().unwrap(),
        m["p95"].as_f64().unwrap(),
        m["max"].as_f64().unwrap(),
    );
    assert!(p5 <= p50 && p50 <= p95 && p95 <= max);
    let failed = a.lines().filter(|l| l.contains(",failed,")).count();
    assert_eq!(summary["failed_trials"].as_u64().unwrap() as usize, failed);
}

#[test]
fn heavy_payloads_fail_and_say_why() {
    let text = std::fs::read_to_string(root().join("scenarios/robustness.toml")).unwrap();
    let text = text.replace(
        "payload_kg = { uniform = [0.0, 2.0] }",
        "payload_kg = { uniform = [95.0, 100.0] }",
    );
    let s = Scenario::parse_with("heavy.toml", &text, &root().join("scenarios"), &[TABLE]).unwrap();
    let spec = SweepSpec::of(&s).unwrap().unwrap();
    let run = run_sweep(&s, &spec, 2, 1, 2, &|| {}).unwrap();
    for r in &run.results {
        assert!(!r.failures.is_empty(), "{r:?}");
        assert!(r.failures.iter().all(|f| Failure::ALL.contains(f)));
    }
}

#[test]
fn bad_sweep_tables_are_refused_by_key() {
    let base = std::fs::read_to_string(root().join("scenarios/thesis-hybrid.toml")).unwrap();
    for (table, key, rule) in [
        (
            "[sweep]\npayload = { uniform = [0.0, 1.0] }",
            "`sweep.payload`",
            "unknown field",
        ),
        (
            "[sweep]\npayload_kg = { uniform = [1.0, 0.0] }",
            "`sweep.payload_kg`",
            "must not exceed",
        ),
        (
            "[sweep]\npayload_kg = { uniform = [0.0, 1.0], normal = [0.0, 1.0] }",
            "`sweep.payload_kg`",
            "exactly one",
        ),
        (
            "[sweep]\npayload_kg = { }",
            "`sweep.payload_kg`",
            "exactly one",
        ),
        (
            "[sweep]\npayload_kg = { uniform = [-1.0, 1.0] }",
            "`sweep.payload_kg`",
            "leaves the key's range",
        ),
        (
            "[sweep]\nlink_mass_scale = { normal = [1.0, 0.5] }",
            "`sweep.link_mass_scale`",
            "6 standard deviations",
        ),
        (
            "[sweep]\nsensor_noise_n = { normal = [1.0] }",
            "`sweep.sensor_noise_n`",
            "two finite numbers",
        ),
        (
            "[sweep]\n",
            "`sweep`",
            "varies nothing; known keys: link_mass_scale, link_inertia_scale, link_com_offset_m, payload_kg, friction_viscous, friction_coulomb, stiffness_n_m, surface_offset_m, sensor_noise_n, sensor_bias_n, fault_start_s, fault_size, fault_duration_s, fault_kinds, max_position_error_mm",
        ),
        (
            "[sweep]\npayload_kg = 3",
            "`sweep.payload_kg`",
            "invalid type: integer, expected a table",
        ),
        (
            "[sweep]\nfault_kinds = \"nan\"",
            "`sweep.fault_kinds`",
            "expected an array of fault kinds",
        ),
        (
            "[sweep]\nstiffness_n_m = { triangular = [1.0, 2.0] }",
            "`sweep.stiffness_n_m",
            "unknown field",
        ),
    ] {
        let s = Scenario::parse_with(
            "s.toml",
            &format!("{base}\n{table}\n"),
            &root().join("scenarios"),
            &[TABLE],
        )
        .unwrap();
        let e = SweepSpec::of(&s).unwrap_err().to_string();
        assert!(
            e.starts_with("s.toml:") && e.contains(key) && e.contains(rule),
            "{table}: {e}"
        );
        // Without the sweep's table named, the scenario reader refuses it.
        let e = Scenario::parse(
            "s.toml",
            &format!("{base}\n{table}\n"),
            &root().join("scenarios"),
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("unknown field `sweep`"), "{e}");
    }
}

/// The SCARA pressing 200 N on a 10 kN/m plane through a noisy sensor (the base of
/// `scenarios/faults/`), without its fault, for `seconds`, with `sweep` as its `[sweep]`.
fn scara_contact_with(sweep: &str, seconds: f64) -> Scenario {
    let text = std::fs::read_to_string(root().join("scenarios/faults/scara-nan.toml")).unwrap();
    let base = text.split("[[faults]]").next().unwrap();
    let text = base.replace(
        "control_dt_s = 0.001",
        &format!("duration_s = {seconds}\ncontrol_dt_s = 0.001"),
    ) + "\n[sweep]\n"
        + sweep;
    Scenario::parse_with(
        "swept.toml",
        &text,
        &root().join("scenarios/faults"),
        &[TABLE],
    )
    .unwrap()
}

#[test]
fn a_thousand_trials_of_normal_sensor_noise_and_bias_never_trip() {
    let s = scara_contact_with(
        "sensor_noise_n = { uniform = [0.0, 3.0] }\nsensor_bias_n = { normal = [0.0, 3.0] }\n",
        6.0,
    );
    let spec = SweepSpec::of(&s).unwrap().unwrap();
    let run = run_sweep(&s, &spec, 1000, 3, 2, &|| {}).unwrap();
    let tripped: Vec<usize> = run
        .results
        .iter()
        .enumerate()
        .filter(|(_, r)| r.failures.contains(&Failure::SafetyTrip))
        .map(|(i, _)| i)
        .collect();
    assert!(tripped.is_empty(), "trials {tripped:?} tripped");
    assert_eq!(run.results.len(), 1000);
}

#[test]
fn drawn_faults_trip_by_kind() {
    let s = scara_contact_with(
        "fault_kinds = [\"nan\", \"dropout\", \"spike\"]\nfault_start_s = { uniform = [3.0, 5.0] }\nfault_size = { uniform = [-2400.0, -500.0] }\nfault_duration_s = { uniform = [0.03, 0.1] }\n",
        6.0,
    );
    let spec = SweepSpec::of(&s).unwrap().unwrap();
    let columns = spec.columns();
    let kind = columns.iter().position(|c| c == "fault_kind").unwrap();
    let run = run_sweep(&s, &spec, 30, 5, 2, &|| {}).unwrap();
    let mut seen = [0; 3];
    for (d, r) in run.draws.iter().zip(&run.results) {
        let k = (d.values[kind].floor() as usize).min(2);
        seen[k] += 1;
        let tripped = r.failures.contains(&Failure::SafetyTrip);
        // A NaN or a dropout beyond the stale time trips; a spike is filtered.
        assert_eq!(tripped, k < 2, "trial {} of kind {k}: {r:?}", d.index);
    }
    assert!(seen.iter().all(|n| *n > 0), "{seen:?}");
    let csv = trials_csv(&spec, &run).unwrap();
    assert!(csv.lines().next().unwrap().contains("fault_kind"));
    assert!(csv.lines().next().unwrap().contains("time_to_trip_s"));
    // A fault key without kinds is refused.
    let text = std::fs::read_to_string(root().join("scenarios/robustness.toml")).unwrap()
        + "fault_start_s = { uniform = [1.0, 2.0] }\n";
    let s = Scenario::parse_with("f.toml", &text, &root().join("scenarios"), &[TABLE]).unwrap();
    let e = SweepSpec::of(&s).unwrap_err().to_string();
    assert!(e.contains("sweep.fault_kinds"), "{e}");
}

#[test]
fn failures_count_trials_and_list_them_by_reason() {
    let trial = |failures: Vec<Failure>| TrialResult {
        metrics: Vec::new(),
        failures,
        error: None,
    };
    let run = SweepRun {
        // Trial numbers that are not the positions, as in a run resumed from a draw.
        draws: [7, 8, 9]
            .map(|index| Draw {
                index,
                values: Vec::new(),
                sensor_seed: 0,
            })
            .to_vec(),
        results: vec![
            trial(vec![Failure::Saturation, Failure::Tracking]),
            trial(Vec::new()),
            trial(vec![Failure::Tracking]),
        ],
        elapsed_s: 0.0,
        threads: 1,
    };
    let FailureSummary { failed, by_reason } = failures(&run);
    assert_eq!(failed, 2);
    let reasons: Vec<Failure> = by_reason.iter().map(|(f, _)| *f).collect();
    assert_eq!(reasons, Failure::ALL);
    let trials_of = |f: Failure| &by_reason.iter().find(|(g, _)| *g == f).unwrap().1;
    assert_eq!(trials_of(Failure::Tracking), &[7, 9]);
    assert_eq!(trials_of(Failure::Saturation), &[7]);
    assert!(trials_of(Failure::EndStop).is_empty());
    assert_eq!(run.results[0].failure_list(), "saturation;tracking");
    assert_eq!(run.results[0].status(), "failed");
    assert_eq!(
        (run.results[1].failure_list(), run.results[1].status()),
        (String::new(), "ok")
    );
}

/// A trial's metrics are its run's: each the number of the run's `metrics.json` of the same
/// name, but for the count of safety trips and the total of end-stop samples.
#[test]
fn a_trials_metrics_are_its_runs() {
    use armdyn::scenario::{execute, metrics_json, prepare};
    use armdyn::sweep::{run_trial, METRICS};
    for file in [
        "scenarios/faults/panda-nan.toml",
        "scenarios/ur5-press-table.toml",
    ] {
        let s = Scenario::load(&root().join(file)).unwrap();
        let trial = run_trial(&s, None);
        let outcome = execute(&s, prepare(&s).unwrap(), |_| {}).unwrap();
        let json = metrics_json(&s, &outcome);
        for (name, value) in METRICS.iter().zip(&trial.metrics) {
            let expected = match *name {
                "safety_trips" => Some(outcome.safety.trips.len() as f64),
                "end_stop_samples_total" => {
                    Some(outcome.stats.end_stop_samples.iter().sum::<usize>() as f64)
                }
                _ => {
                    // Every other metric is a key of the file: a number, or null where the
                    // run does not define it.
                    let v = json
                        .get(name)
                        .unwrap_or_else(|| panic!("{file}: no {name}"));
                    assert!(v.is_number() || v.is_null(), "{file}: {name} = {v}");
                    v.as_f64()
                }
            };
            assert_eq!(*value, expected, "{file}: {name}");
        }
        let defined = trial.metrics.iter().filter(|m| m.is_some()).count();
        assert!(defined >= 20, "{file}: {:?}", trial.metrics);
    }
    // The faulted run trips; the nominal one does not.
    let trips = |file: &str| {
        let s = Scenario::load(&root().join(file)).unwrap();
        let i = METRICS.iter().position(|m| *m == "safety_trips").unwrap();
        run_trial(&s, None).metrics[i]
    };
    assert!(trips("scenarios/faults/panda-nan.toml").unwrap() >= 1.0);
    assert_eq!(trips("scenarios/ur5-press-table.toml"), Some(0.0));
}
