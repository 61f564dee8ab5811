//! `armdyn identify` and `armdyn sweep` end to end: their files on success, and on bad input a
//! clear error, a non-zero exit and nothing written.

use crate::common::{armdyn, s, tmp};

/// The prefix of this file's temporary folders.
const AREA: &str = "idsw";

#[test]
fn identify_writes_the_json_and_the_figure_and_a_controller_reads_it() {
    let dir = tmp(AREA, "identify");
    let out = dir.join("id");
    let o = armdyn(&[
        "identify",
        "--robot",
        "scara",
        "--noise-pct",
        "1",
        "--friction",
        "on",
        "--seed",
        "2",
        "--out",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("identification.json")).unwrap())
            .unwrap();
    assert_eq!(v["robot"], "scara");
    assert_eq!(v["base_parameter_count"], 16);
    assert_eq!(v["base_parameter_names"].as_array().unwrap().len(), 16);
    assert!(v["validation_torque_rms_error_pct"]
        .as_array()
        .unwrap()
        .iter()
        .all(|e| e.as_f64().unwrap() <= 2.0));
    assert!(std::fs::read_to_string(out.join("validation_torques.svg"))
        .unwrap()
        .starts_with("<svg"));
    let json = out.join("identification.json");
    let run = dir.join("run");
    let o = armdyn(&[
        "run",
        "hybrid",
        "--controller-model",
        s(&json),
        "--out",
        s(&run),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(run.join("metrics.json")).unwrap()).unwrap();
    assert!(m["controller_model"]
        .as_str()
        .unwrap()
        .contains("identification.json"));
    // Bad input: nothing written.
    let bad = dir.join("bad");
    let o = armdyn(&[
        "identify",
        "--robot",
        "scara",
        "--noise-pct",
        "-1",
        "--out",
        s(&bad),
    ]);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("--noise-pct"));
    assert!(!bad.exists());
    let o = armdyn(&[
        "run",
        "hybrid",
        "--controller-model",
        "no/such.json",
        "--out",
        s(&bad),
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("--controller-model") && e.contains("no/such.json"),
        "{e}"
    );
    assert!(!bad.exists());
}

#[test]
fn sweep_writes_its_files_and_refuses_a_file_without_sweep() {
    let dir = tmp(AREA, "sweep");
    let out = dir.join("sw");
    let o = armdyn(&[
        "sweep",
        "scenarios/robustness.toml",
        "--samples",
        "4",
        "--seed",
        "3",
        "--threads",
        "2",
        "--out",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Not a terminal: no progress bar.
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let csv = std::fs::read_to_string(out.join("trials.csv")).unwrap();
    assert_eq!(csv.lines().count(), 5);
    assert!(csv.starts_with("trial,link_mass_scale_1,"));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["samples"], 4);
    assert!(out
        .join("histogram_normal_force_overshoot_pct.svg")
        .exists());
    let bad = dir.join("bad");
    let o = armdyn(&[
        "sweep",
        "scenarios/thesis-hybrid.toml",
        "--samples",
        "4",
        "--out",
        s(&bad),
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("thesis-hybrid.toml") && e.contains("[sweep]"),
        "{e}"
    );
    assert!(!bad.exists());
}

#[test]
fn identify_takes_every_generated_robot_and_names_them_for_an_unknown_one() {
    let dir = tmp(AREA, "identify-ur5");
    let out = dir.join("ur5");
    let o = armdyn(&[
        "identify",
        "--robot",
        "ur5",
        "--evaluations",
        "50",
        "--out",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("identification.json")).unwrap())
            .unwrap();
    assert_eq!(j["robot"], "ur5");
    assert_eq!(j["parameter_names"].as_array().unwrap().len(), 60);
    let o = armdyn(&["identify", "--robot", "kuka", "--out", s(&dir.join("bad"))]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("--robot kuka") && e.contains("panda"),
        "{e}"
    );
    assert!(!dir.join("bad").exists());
}
