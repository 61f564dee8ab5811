//! `armdyn run joint-reference`: every generated robot tracks a smooth joint trajectory with
//! computed torque; the Panda on the shipped trajectory `scenarios/joint-reference/panda-smooth.csv`
//! (`q_i(t) = home_i + a_i sin^2(pi t / 3)`, 0 to 3 s, samples every 10 ms) stays within 1e-4 rad
//! after 1 s; bad reference files are errors naming the line and column.

use std::path::Path;

use crate::command::armdyn;
use crate::scratch::Scratch;

use approx::{abs_diff_eq, assert_abs_diff_eq};
use armdyn::model::{RobotModel, ROBOTS};

fn temp_dir(tag: &str) -> Scratch {
    Scratch::new(&format!("joint-ref-{tag}"))
}

fn metrics(out: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(out.join("metrics.json")).expect("metrics.json");
    serde_json::from_str(&text).expect("JSON")
}

const HOME: [f64; 7] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
const AMPLITUDE: [f64; 7] = [0.5, 0.3, -0.4, 0.5, 0.6, -0.4, 0.8];

#[test]
fn shipped_panda_trajectory_is_the_stated_one() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/joint-reference/panda-smooth.csv");
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("t,q1,q2,q3,q4,q5,q6,q7"));
    let mut count = 0;
    for (k, line) in lines.enumerate() {
        let values: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let t = k as f64 * 0.01;
        assert_abs_diff_eq!(values[0], t, epsilon = 1e-12);
        let s = (std::f64::consts::PI * t / 3.0).sin().powi(2);
        for i in 0..7 {
            assert!(
                abs_diff_eq!(values[i + 1], HOME[i] + AMPLITUDE[i] * s, epsilon = 1e-12),
                "line {k}"
            );
        }
        count += 1;
    }
    assert_eq!(count, 301);
}

#[test]
fn panda_with_computed_torque_tracks_within_1e_4_rad_after_1_s() {
    let out = temp_dir("panda");
    let csv =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/joint-reference/panda-smooth.csv");
    let output = armdyn(&[
        "run",
        "joint-reference",
        "--robot",
        "panda",
        "--csv",
        csv.to_str().unwrap(),
        "--controller",
        "computed-torque",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let m = metrics(&out);
    let max = m["max_abs_joint_error_after"].as_f64().unwrap();
    assert!(max < 1e-4, "max joint error after 1 s: {max}");
    assert!(max > 0.0, "a sampled controller cannot track exactly");
    for name in ["trajectory.csv", "joints.svg", "joint_errors.svg"] {
        assert!(out.join(name).is_file(), "{name}");
    }
    let header = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    assert!(header.starts_with("t_s,panda_joint1_rad,"));
}

/// A smooth trajectory about the middle of each joint's range (10 % of the range), 2 s.
fn smooth_csv<const N: usize, R: RobotModel<N>>() -> String {
    let mut text = String::from("t");
    for i in 1..=N {
        text += &format!(",q{i}");
    }
    text.push('\n');
    for k in 0..=200 {
        let t = k as f64 * 0.01;
        let s = (std::f64::consts::PI * t / 2.0).sin().powi(2);
        text += &format!("{t}");
        for [lo, hi] in R::JOINT_LIMITS {
            let (mid, range) = (0.5 * (lo + hi), hi - lo);
            text += &format!(",{}", mid + 0.1 * range.min(2.0) * s);
        }
        text.push('\n');
    }
    text
}

#[test]
fn every_generated_robot_tracks_a_joint_trajectory() {
    for &robot in ROBOTS {
        let dir = temp_dir(&format!("every-{robot}"));
        let csv = dir.join("reference.csv");
        std::fs::write(
            &csv,
            armdyn::with_robot_named!(robot, |_robot: R, N, _module| smooth_csv::<N, R>()).unwrap(),
        )
        .unwrap();
        for controller in ["computed-torque", "pid-fl"] {
            let out = dir.join(controller);
            let output = armdyn(&[
                "run",
                "joint-reference",
                "--robot",
                robot,
                "--csv",
                csv.to_str().unwrap(),
                "--controller",
                controller,
                "--out",
                out.to_str().unwrap(),
            ]);
            assert!(
                output.status.success(),
                "{robot} {controller}: {}",
                String::from_utf8_lossy(&output.stderr)
            );
            let max = metrics(&out)["max_abs_joint_error_after"].as_f64().unwrap();
            let bound = if controller == "computed-torque" {
                1e-4
            } else {
                0.05
            };
            assert!(
                max < bound,
                "{robot} {controller}: max error after 1 s {max}"
            );
        }
    }
}

#[test]
fn bad_reference_files_are_errors_naming_line_and_column() {
    let dir = temp_dir("bad");
    let cases = [
        (
            "t,q1,q2\n0,0,0\n",
            "line 1: the header must be `t,q1,q2,q3,q4,q5,q6`",
        ),
        (
            "t,q1,q2,q3,q4,q5,q6\n0,0,0,0,0,0,0\n0.1,0,0,0,x,0,0\n",
            "line 3, column 5 (`q4`)",
        ),
        (
            "t,q1,q2,q3,q4,q5,q6\n0,0,0,0,0,0,0\n0,0,0,0,0,0,0\n",
            "line 3, column 1 (`t`): time 0 s",
        ),
    ];
    for (k, (text, needle)) in cases.iter().enumerate() {
        let csv = dir.join(format!("bad{k}.csv"));
        std::fs::write(&csv, text).unwrap();
        let out = dir.join(format!("out{k}"));
        let output = armdyn(&[
            "run",
            "joint-reference",
            "--robot",
            "ur5",
            "--csv",
            csv.to_str().unwrap(),
            "--controller",
            "computed-torque",
            "--out",
            out.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success());
        assert!(stderr.contains(needle), "{needle:?} not in {stderr}");
        assert!(stderr.contains(csv.to_str().unwrap()), "{stderr}");
        assert!(!out.exists(), "nothing written on error");
    }
}
