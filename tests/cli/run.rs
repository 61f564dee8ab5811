//! `armdyn run`, `armdyn simulate` and the default command end to end: outputs on success,
//! and on bad input a clear error, a non-zero exit and no partial output.

use std::path::Path;
use std::process::Output;

use crate::common::{armdyn_in, stderr, tmp};
use approx::{abs_diff_eq, assert_abs_diff_eq};

/// The prefix of this file's temporary folders.
const AREA: &str = "run";

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = match std::fs::read_dir(dir) {
        Ok(rd) => rd
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect(),
        Err(_) => vec![],
    };
    v.sort();
    v
}

fn assert_fails_cleanly(o: &Output, needle: &str, out: &Path) {
    assert!(
        !o.status.success(),
        "expected failure; stdout {}",
        String::from_utf8_lossy(&o.stdout)
    );
    let err = stderr(o);
    assert!(
        err.contains(needle),
        "stderr should mention {needle:?}:\n{err}"
    );
    assert!(
        files_in(out).is_empty(),
        "partial output left in {}: {:?}",
        out.display(),
        files_in(out)
    );
}

#[test]
fn default_command_runs_the_hybrid_trial() {
    let dir = tmp(AREA, "default");
    let o = armdyn_in(&[], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("hybrid pi-ff-vd const"), "{stdout}");
    let out = dir.join("out/hybrid");
    for f in [
        "trajectory.csv",
        "metrics.json",
        "path.svg",
        "joints.svg",
        "joint_errors.svg",
        "cartesian.svg",
        "force.svg",
    ] {
        assert!(out.join(f).is_file(), "missing {f}");
    }
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("metrics.json")).unwrap()).unwrap();
    for key in [
        "force_overshoot_pct",
        "settling_time_s",
        "force_rms_error_last5s_n",
        "xy_rms_error_contact_mm",
        "min_z_m",
        "controller",
        "gains",
    ] {
        assert!(m.get(key).is_some(), "metrics.json lacks {key}");
    }
    let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    assert!(
        header.contains("fz_N") && header.contains("fz_ref_N"),
        "{header}"
    );
    assert_eq!(csv.lines().count(), 10_002);
}

#[test]
fn position_run_writes_metrics_with_gains() {
    let dir = tmp(AREA, "position");
    let o = armdyn_in(
        &["run", "position", "--controller", "pid", "--out", "p"],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("p/metrics.json")).unwrap())
            .unwrap();
    assert_eq!(m["controller"], "pid");
    assert_abs_diff_eq!(
        m["gains"]["kp"][0].as_f64().unwrap(),
        1347.94,
        epsilon = 1.5
    );
    for key in [
        "rms_joint_error",
        "rms_joint_error_after_2s",
        "max_joint_error_after_2s",
        "max_abs_tau",
    ] {
        assert_eq!(m[key].as_array().map(Vec::len), Some(4), "{key}");
    }
}

#[test]
fn unknown_names_are_refused() {
    let dir = tmp(AREA, "names");
    let out = dir.join("o");
    let o = armdyn_in(
        &["run", "position", "--controller", "pdi", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(&o, "unknown controller `pdi`", &out);
    let o = armdyn_in(
        &["run", "hybrid", "--force-controller", "pid", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(&o, "unknown force controller `pid`", &out);
    let o = armdyn_in(
        &["run", "hybrid", "--force", "sometimes", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(&o, "unknown force reference `sometimes`", &out);
    let o = armdyn_in(&["run", "circle", "--out", "o"], &dir);
    assert_fails_cleanly(&o, "circle", &out);
}

fn torque_case(name: &str, csv: &str, needle: &str) {
    let dir = tmp(AREA, name);
    std::fs::write(dir.join("tau.csv"), csv).unwrap();
    let o = armdyn_in(&["simulate", "--torque-csv", "tau.csv", "--out", "o"], &dir);
    assert_fails_cleanly(&o, needle, &dir.join("o"));
}

#[test]
fn malformed_torque_csv_is_refused() {
    torque_case(
        "missing",
        "t,tau1,tau2,tau3\n0,0,0,0\n",
        "missing column `tau4`",
    );
    torque_case(
        "nonnum",
        "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n0.1,0,abc,0,0\n",
        "tau.csv (robot scara, 4 joints): line 3, column 3 (`tau2`): `abc` is not a number",
    );
    torque_case(
        "order",
        "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n0.2,0,0,0,0\n0.1,0,0,0,0\n",
        "line 4, column 1 (`t`): time 0.1 s is not after",
    );
    torque_case(
        "nan",
        "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n0.1,NaN,0,0,0\n",
        "line 3, column 2 (`tau1`): NaN is not finite",
    );
}

#[test]
fn non_finite_simulation_state_is_an_error_naming_the_time() {
    // 1e300 N m on a 3 kg m^2 joint overflows within one step.
    torque_case(
        "blowup",
        "t,tau1,tau2,tau3,tau4\n0,1e300,1e300,0,0\n1,0,0,0,0\n",
        "non-finite state at t =",
    );
}

#[test]
fn open_loop_simulation_writes_the_documented_header() {
    let dir = tmp(AREA, "open-loop");
    // Holding gravity on d3 keeps the arm still; a torque on q1 turns it.
    std::fs::write(
        dir.join("tau.csv"),
        "t,tau1,tau2,tau3,tau4\n0,1,0,-48.412,0\n0.5,0,0,-48.412,0\n1,0,0,-48.412,0\n",
    )
    .unwrap();
    let o = armdyn_in(
        &[
            "simulate",
            "--torque-csv",
            "tau.csv",
            "--out",
            "o",
            "--q0",
            "0,0.5,0.2,0",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("o/trajectory.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("t,q1,q2,q3,q4,qd1,qd2,qd3,qd4"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 3);
    assert_eq!(rows[1][0], 0.5);
    assert!(rows[2][1] > 0.0, "q1 turned: {:?}", rows[2]);
    assert!(
        abs_diff_eq!(rows[2][3], 0.2, epsilon = 1e-9),
        "d3 held by the gravity torque: {:?}",
        rows[2]
    );
}

#[test]
fn unreachable_reference_is_refused_before_simulating() {
    let dir = tmp(AREA, "unreachable");
    std::fs::write(
        dir.join("ref.csv"),
        "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.9,0,0.2,0\n2,0.5,0,0.2,0\n",
    )
    .unwrap();
    let o = armdyn_in(
        &["run", "reference", "--csv", "ref.csv", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(&o, "nothing was simulated", &dir.join("o"));
    let o = armdyn_in(
        &["run", "reference", "--csv", "missing.csv", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(&o, "missing.csv", &dir.join("o"));
    std::fs::write(dir.join("bad.csv"), "t,x,y,yaw\n0,0.5,0,0\n").unwrap();
    let o = armdyn_in(
        &["run", "reference", "--csv", "bad.csv", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(&o, "bad.csv", &dir.join("o"));
}

#[test]
fn a_failed_run_leaves_earlier_output_untouched() {
    let dir = tmp(AREA, "untouched");
    std::fs::write(
        dir.join("tau.csv"),
        "t,tau1,tau2,tau3,tau4\n0,0,0,-48.412,0\n0.1,0,0,-48.412,0\n",
    )
    .unwrap();
    let o = armdyn_in(&["simulate", "--torque-csv", "tau.csv", "--out", "o"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let before = std::fs::read(dir.join("o/trajectory.csv")).unwrap();
    std::fs::write(
        dir.join("tau.csv"),
        "t,tau1,tau2,tau3,tau4\n0,1e300,1e300,0,0\n1,0,0,0,0\n",
    )
    .unwrap();
    let o = armdyn_in(&["simulate", "--torque-csv", "tau.csv", "--out", "o"], &dir);
    assert!(!o.status.success());
    assert_eq!(std::fs::read(dir.join("o/trajectory.csv")).unwrap(), before);
    assert_eq!(files_in(&dir.join("o")), vec!["trajectory.csv".to_string()]);
}

/// A torque file as a spreadsheet program saves it: a UTF-8 byte-order mark, CRLF line ends.
#[test]
fn torque_csv_with_byte_order_mark_and_crlf_is_read() {
    let dir = tmp(AREA, "bom");
    let plain = "t,tau1,tau2,tau3,tau4\n0,1,0,-48.412,0\n0.5,0,0,-48.412,0\n";
    let mut outputs = Vec::new();
    for (name, text) in [
        ("plain", plain.to_string()),
        ("bom", format!("\u{feff}{plain}")),
        ("crlf", plain.replace('\n', "\r\n")),
        (
            "bom-crlf",
            format!("\u{feff}{}", plain.replace('\n', "\r\n")),
        ),
    ] {
        std::fs::write(dir.join(format!("{name}.csv")), text).unwrap();
        let o = armdyn_in(
            &[
                "simulate",
                "--torque-csv",
                &format!("{name}.csv"),
                "--out",
                name,
            ],
            &dir,
        );
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        outputs.push(std::fs::read(dir.join(name).join("trajectory.csv")).unwrap());
    }
    assert!(outputs.iter().all(|o| o == &outputs[0]));
    // Errors still name the right line.
    torque_case(
        "bom-error",
        "\u{feff}t,tau1,tau2,tau3,tau4\r\n0,0,0,0,0\r\n\r\n1,0,x,0,0\r\n",
        "tau.csv (robot scara, 4 joints): line 4, column 3 (`tau2`): `x` is not a number",
    );
}

#[test]
fn reference_csv_with_byte_order_mark_and_crlf_is_read() {
    let dir = tmp(AREA, "ref-bom");
    let plain = "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.5,0.1,0.2,0\n";
    std::fs::write(
        dir.join("ref.csv"),
        format!("\u{feff}{}", plain.replace('\n', "\r\n")),
    )
    .unwrap();
    let o = armdyn_in(
        &["run", "reference", "--csv", "ref.csv", "--out", "o"],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("o/trajectory.csv").is_file());
}

/// A run longer than `--max-steps` plant steps is refused before it starts, naming the
/// count and the option; the option lets it run.
#[test]
fn runs_beyond_the_step_limit_are_refused_before_they_start() {
    let dir = tmp(AREA, "limit");
    let out = dir.join("o");
    std::fs::write(
        dir.join("tau.csv"),
        "t,tau1,tau2,tau3,tau4\n0,0,0,-48.412,0\n1e9,0,0,-48.412,0\n",
    )
    .unwrap();
    let start = std::time::Instant::now();
    let o = armdyn_in(&["simulate", "--torque-csv", "tau.csv", "--out", "o"], &dir);
    assert_fails_cleanly(
        &o,
        "tau.csv: the run would take 1000000000000 plant steps (t from 0 to 1e9 s in steps of \
         at most 0.001 s), more than the limit of 100000000 (--max-steps); nothing was \
         simulated. To run it anyway, pass --max-steps 1000000000000",
        &out,
    );
    let o = armdyn_in(
        &["run", "hybrid", "--plant-dt", "1e-10", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(
        &o,
        "hybrid pi-ff-vd const: the run would take 100000000000 plant steps (10 s at a plant \
         step of 1e-10 s)",
        &out,
    );
    std::fs::write(
        dir.join("ref.csv"),
        "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1e9,0.5,0.1,0.2,0\n",
    )
    .unwrap();
    let o = armdyn_in(
        &["run", "reference", "--csv", "ref.csv", "--out", "o"],
        &dir,
    );
    assert_fails_cleanly(&o, "pass --max-steps 1000000000000", &out);
    // Allowed, the same reference at 10 ns cannot keep its 1e17 samples (464 bytes each,
    // beyond any address space) in memory: refused at once, not after planning it.
    let o = armdyn_in(
        &[
            "run",
            "reference",
            "--csv",
            "ref.csv",
            "--out",
            "o",
            "--control-dt",
            "1e-8",
            "--plant-dt",
            "1e-8",
            "--max-steps",
            "100000000000000000",
        ],
        &dir,
    );
    assert_fails_cleanly(
        &o,
        "the run would keep 100000000000000001 control samples",
        &out,
    );
    assert!(
        start.elapsed().as_secs() < 60,
        "refusals come before any simulation"
    );
    // Scenario files too, before their reference is planned.
    let scenario = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/thesis-position.toml"),
    )
    .unwrap()
    .replace("plant_dt_s = 0.001", "plant_dt_s = 1e-9");
    std::fs::write(dir.join("fine.toml"), scenario).unwrap();
    let o = armdyn_in(&["run", "scenario", "fine.toml", "--out", "o"], &dir);
    assert_fails_cleanly(
        &o,
        "thesis-position: the run would take 10000000000 plant steps (10 s at a plant step of \
         1e-9 s)",
        &out,
    );
    // The exact count includes the pause a planned elbow flip adds to the three-zone trial.
    let o = armdyn_in(
        &["run", "three-zone", "--out", "o", "--max-steps", "10000"],
        &dir,
    );
    assert_fails_cleanly(
        &o,
        "s at a plant step of 0.001 s), more than the limit of 10000",
        &out,
    );
    // A lower limit refuses the thesis trial; one at its length lets it run.
    let o = armdyn_in(
        &[
            "run",
            "position",
            "--controller",
            "pid",
            "--out",
            "o",
            "--max-steps",
            "9999",
        ],
        &dir,
    );
    assert_fails_cleanly(
        &o,
        "would take 10000 plant steps (10 s at a plant step of 0.001 s)",
        &out,
    );
    let o = armdyn_in(
        &[
            "run",
            "position",
            "--controller",
            "pid",
            "--out",
            "o",
            "--max-steps",
            "10000",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    std::fs::write(
        dir.join("short.csv"),
        "t,tau1,tau2,tau3,tau4\n0,0,0,-48.412,0\n0.01,0,0,-48.412,0\n",
    )
    .unwrap();
    let o = armdyn_in(
        &[
            "simulate",
            "--torque-csv",
            "short.csv",
            "--out",
            "s",
            "--max-steps",
            "9",
        ],
        &dir,
    );
    assert_fails_cleanly(&o, "would take 10 plant steps", &dir.join("s"));
    let o = armdyn_in(
        &[
            "simulate",
            "--torque-csv",
            "short.csv",
            "--out",
            "s",
            "--max-steps",
            "10",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_scenario_runs_with_the_deployable_step_in_single_precision() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = tmp(AREA, "precision");
    let out = dir.join("out");
    let o = armdyn_in(
        &[
            "run",
            "scenario",
            "scenarios/thesis-hybrid.toml",
            "--precision",
            "f32",
            "--out",
            out.to_str().unwrap(),
        ],
        root,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let metrics: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("metrics.json")).unwrap()).unwrap();
    assert_eq!(metrics["controller"], "hybrid-pi-ff-vd-f32");
    // A scenario it cannot run: refused before simulating, naming the key; nothing written.
    let refused = dir.join("refused");
    let o = armdyn_in(
        &[
            "run",
            "scenario",
            "scenarios/sphere-patch.toml",
            "--precision",
            "f32",
            "--out",
            refused.to_str().unwrap(),
        ],
        root,
    );
    assert_fails_cleanly(&o, "`surfaces[0]`: the deployable step", &refused);
    let o = armdyn_in(
        &[
            "run",
            "scenario",
            "scenarios/thesis-hybrid.toml",
            "--precision",
            "f16",
        ],
        root,
    );
    assert!(!o.status.success());
    assert!(stderr(&o).contains("f16"), "{}", stderr(&o));
}
