//! The thesis trials as scenario files reproduce the metrics the trial code wrote before they
//! became files (`tests/data/thesis-baseline/`, see its README) to 1e-9.

use std::path::{Path, PathBuf};

use crate::command::{armdyn, stderr};
use crate::scratch::Scratch;

use serde_json::Value;

use armdyn::scenario::{execute, metrics_json, prepare, Scenario};

/// Relative tolerance on every number (absolute below 1).
const TOLERANCE: f64 = 1e-9;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn baseline(name: &str) -> Value {
    let path = root()
        .join("tests/data/thesis-baseline")
        .join(format!("{name}.json"));
    serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

/// Every number and string of `expected` (but the free-text keys) equals `actual`'s.
fn compare(expected: &Value, actual: &Value, path: &str, diffs: &mut Vec<String>) {
    match (expected, actual) {
        (Value::Object(e), Value::Object(a)) => {
            for (k, v) in e {
                if ["trial", "note", "scenario"].contains(&k.as_str()) {
                    continue;
                }
                match a.get(k) {
                    Some(w) => compare(v, w, &format!("{path}.{k}"), diffs),
                    None => diffs.push(format!("{path}.{k}: missing")),
                }
            }
        }
        (Value::Array(e), Value::Array(a)) if e.len() == a.len() => {
            for (i, (v, w)) in e.iter().zip(a).enumerate() {
                compare(v, w, &format!("{path}[{i}]"), diffs);
            }
        }
        (Value::Number(e), Value::Number(a)) => {
            let (e, a) = (e.as_f64().unwrap(), a.as_f64().unwrap());
            if (e - a).abs() > TOLERANCE * e.abs().max(1.0) {
                diffs.push(format!("{path}: {e} (baseline) vs {a}"));
            }
        }
        (e, a) if e == a => {}
        (e, a) => diffs.push(format!("{path}: {e} (baseline) vs {a}")),
    }
}

fn assert_matches(name: &str, actual: &Value) {
    let mut diffs = Vec::new();
    compare(&baseline(name), actual, name, &mut diffs);
    assert!(
        diffs.is_empty(),
        "{name} differs from its baseline:\n{}",
        diffs.join("\n")
    );
}

fn run_file(file: &str) -> Value {
    let s = Scenario::load(&root().join("scenarios").join(file)).unwrap();
    let p = prepare(&s).unwrap();
    let r = execute(&s, p, |_| {}).unwrap();
    metrics_json(&s, &r)
}

#[test]
fn shipped_thesis_scenario_files_reproduce_the_trials() {
    for (file, name) in [
        ("thesis-hybrid.toml", "hybrid-pi-ff-vd-const"),
        ("thesis-hybrid-variable.toml", "hybrid-pi-ff-vd-var"),
        ("thesis-position.toml", "position-pid-fl"),
        ("thesis-contact.toml", "contact"),
        ("thesis-three-zone.toml", "three-zone"),
    ] {
        assert_matches(name, &run_file(file));
    }
}

fn metrics_in(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("metrics.json")).unwrap()).unwrap()
}

#[test]
fn every_thesis_trial_of_the_command_line_reproduces_its_baseline() {
    let out = Scratch::new("thesis-baseline");
    let armdyn = |args: &[&str]| {
        let o = armdyn(args);
        assert!(o.status.success(), "{}", stderr(&o));
    };
    let dir = |d: &str| out.join(d).to_str().unwrap().to_string();
    // The thesis's trials ran without a supervisor, and its PI + FF laws diverge: their
    // baselines are unsupervised (supervised, they trip; see the table's safety column).
    armdyn(&[
        "run",
        "hybrid",
        "--all",
        "--no-safety",
        "--out",
        &dir("hybrid"),
    ]);
    armdyn(&["run", "position", "--all", "--out", &dir("position")]);
    armdyn(&["run", "contact", "--out", &dir("contact")]);
    armdyn(&[
        "run",
        "three-zone",
        "--elbow-switch",
        "step",
        "--out",
        &dir("three-zone"),
    ]);
    armdyn(&[
        "run",
        "hybrid",
        "--sensor-noise",
        "5",
        "--seed",
        "3",
        "--out",
        &dir("noise"),
    ]);
    for combo in ["pi-ff-const", "pi-ff-var", "pi-ff-vd-const", "pi-ff-vd-var"] {
        assert_matches(
            &format!("hybrid-{combo}"),
            &metrics_in(&out.join("hybrid").join(combo)),
        );
    }
    for c in [
        "pid",
        "pid-fl",
        "fsf-place",
        "fsf-lqr",
        "pid-fl-central",
        "computed-torque",
    ] {
        assert_matches(
            &format!("position-{c}"),
            &metrics_in(&out.join("position").join(c)),
        );
    }
    assert_matches("contact", &metrics_in(&out.join("contact")));
    assert_matches("three-zone", &metrics_in(&out.join("three-zone")));
    assert_matches("hybrid-noise5", &metrics_in(&out.join("noise")));
}
