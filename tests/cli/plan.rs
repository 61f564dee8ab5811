//! `armdyn plan` end to end: the plan's CSV is a joint reference a scenario runs as it is.

use crate::common::{armdyn_in, stderr, tmp};

const AREA: &str = "plan";

/// The UR5's minimum-effort move, written by `--csv` and named by a `kind = "joints"`
/// scenario as it is: computed torque follows it with no saturated sample, no end stop and
/// millirad errors.
#[test]
fn a_plan_csv_runs_as_a_joint_reference() {
    let dir = tmp(AREA, "joints");
    let o = armdyn_in(
        &[
            "plan",
            "--robot",
            "ur5",
            "--from",
            "0,-1.5,1.2,-1,-1.5,0",
            "--to",
            "1.5,-1,0.5,-1.5,-1,1",
            "--duration",
            "1",
            "--limit-margin",
            "0.05",
            "--csv",
            "plan.csv",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    std::fs::write(
        dir.join("move.toml"),
        "format = 1\nname = \"ur5-planned-move\"\nrobot = \"ur5\"\nstart_on_reference = true\n\
         duration_s = 2.5\n\n[reference]\nkind = \"joints\"\nfile = \"plan.csv\"\n\n\
         [position]\nlaw = \"computed-torque\"\n",
    )
    .unwrap();
    let o = armdyn_in(&["run", "scenario", "move.toml", "--out", "o"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let m: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("o/metrics.json")).unwrap()).unwrap();
    assert_eq!(m["saturated_samples_total"], 0, "{m}");
    assert_eq!(m["joint_limit_violation_samples"], 0, "{m}");
    let worst = m["rms_joint_error"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_f64().unwrap())
        .fold(0.0, f64::max);
    assert!(worst < 5e-3, "{m}");
    // At rest at the goal after the move (it ends at 1 s; the run goes on to 2.5 s).
    let after = m["rms_joint_error_after_2s"].as_array().unwrap();
    assert!(after.iter().all(|e| e.as_f64().unwrap() < 1e-5), "{m}");
}
