//! `armdyn model` end to end: the JSON it prints, and its errors on bad input.

use std::process::Output;

use crate::common::{armdyn, tmp};
use approx::assert_abs_diff_eq;
use serde_json::Value;

fn json_of(output: &Output) -> Value {
    assert!(
        output.status.success(),
        "exit {:?}, stderr: {}",
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("stdout is one JSON value")
}

/// Shape of a nested array of numbers: `[rows, cols]` or `[len]`.
fn shape(value: &Value) -> Vec<usize> {
    let array = value.as_array().expect("an array");
    match array.first() {
        Some(Value::Array(_)) => {
            let inner = shape(&array[0]);
            for row in array {
                assert_eq!(shape(row), inner, "ragged array");
            }
            [vec![array.len()], inner].concat()
        }
        _ => {
            assert!(
                array.iter().all(Value::is_number),
                "non-numeric entry in {value}"
            );
            vec![array.len()]
        }
    }
}

fn as_f64(value: &Value) -> f64 {
    value.as_f64().expect("a number")
}

fn stderr_of(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn assert_fails_with(args: &[&str], needles: &[&str]) {
    let output = armdyn(args);
    let stderr = stderr_of(&output);
    assert!(
        !output.status.success(),
        "{args:?} succeeded: {}",
        String::from_utf8_lossy(&output.stdout)
    );
    assert!(output.stdout.is_empty(), "{args:?} printed to stdout");
    for needle in needles {
        assert!(
            stderr.contains(needle),
            "{args:?}: stderr lacks {needle:?}:\n{stderr}"
        );
    }
    assert!(!stderr.contains("panicked"), "{args:?} panicked:\n{stderr}");
}

#[test]
fn prints_one_json_object_with_every_key_and_shape() {
    // Every robot of the generated registry.
    macro_rules! robots_and_dofs {
        ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
            [$((stringify!($module), $n)),*]
        };
    }
    let robots = armdyn_generated::for_each_robot!(robots_and_dofs);
    assert!(robots.len() >= 6, "the registry lists {robots:?}");
    for (robot, n) in robots {
        let q: Vec<String> = (0..n)
            .map(|i| format!("{}", 0.1 * i as f64 + 0.1))
            .collect();
        let qd: Vec<String> = (0..n).map(|i| format!("{}", -0.2 * i as f64)).collect();
        let (q, qd) = (q.join(","), qd.join(","));
        let output = armdyn(&["model", "--robot", robot, "--q", &q, "--qd", &qd]);
        let value = json_of(&output);
        let object = value.as_object().expect("a JSON object");
        let expected = [
            "robot",
            "q",
            "qd",
            "pose",
            "jacobian",
            "mass_matrix",
            "coriolis_matrix",
            "coriolis",
            "gravity",
        ];
        let mut keys: Vec<&str> = object.keys().map(String::as_str).collect();
        keys.sort_unstable();
        let mut sorted = expected.to_vec();
        sorted.sort_unstable();
        assert_eq!(keys, sorted, "{robot}: keys");
        // Printed in the documented order.
        let text = String::from_utf8_lossy(&output.stdout);
        let positions: Vec<usize> = expected
            .iter()
            .map(|key| text.find(&format!("\"{key}\":")).expect("key printed"))
            .collect();
        assert!(
            positions.windows(2).all(|w| w[0] < w[1]),
            "{robot}: key order {positions:?}"
        );
        assert_eq!(object["robot"], robot);
        assert_eq!(shape(&object["q"]), [n]);
        assert_eq!(shape(&object["qd"]), [n]);
        assert_eq!(shape(&object["pose"]), [4, 4]);
        assert_eq!(shape(&object["jacobian"]), [6, n]);
        assert_eq!(shape(&object["mass_matrix"]), [n, n]);
        assert_eq!(shape(&object["coriolis_matrix"]), [n, n]);
        assert_eq!(shape(&object["coriolis"]), [n]);
        assert_eq!(shape(&object["gravity"]), [n]);
        assert_abs_diff_eq!(
            as_f64(&object["q"][n - 1]),
            0.1 * (n - 1) as f64 + 0.1,
            epsilon = 1e-15
        );
        assert_abs_diff_eq!(as_f64(&object["qd"][1]), -0.2, epsilon = 1e-15);
        // Last row of a homogeneous transform.
        let last: Vec<f64> = object["pose"][3]
            .as_array()
            .unwrap()
            .iter()
            .map(as_f64)
            .collect();
        assert_eq!(last, [0.0, 0.0, 0.0, 1.0]);
    }
}

#[test]
fn defaults_and_thesis_values_for_the_scara() {
    // --q and --qd default to zeros; --robot defaults to scara.
    let value = json_of(&armdyn(&["model", "--compact"]));
    assert_eq!(value["robot"], "scara");
    assert_eq!(value["q"], serde_json::json!([0.0, 0.0, 0.0, 0.0]));
    assert_abs_diff_eq!(as_f64(&value["pose"][0][3]), 0.8, epsilon = 1e-12);
    assert_abs_diff_eq!(as_f64(&value["pose"][2][3]), 0.35, epsilon = 1e-12);
    assert_abs_diff_eq!(as_f64(&value["gravity"][2]), -48.412, epsilon = 1e-9);
    assert_abs_diff_eq!(as_f64(&value["mass_matrix"][2][2]), 4.94, epsilon = 1e-12);
    // Negative values, both as a separate word and with `=`.
    let a = json_of(&armdyn(&[
        "model",
        "--q",
        "-0.5,0.3,0.2,-1",
        "--qd",
        "1,-1,0,0",
    ]));
    let b = json_of(&armdyn(&["model", "--q=-0.5,0.3,0.2,-1", "--qd=1,-1,0,0"]));
    assert_eq!(a, b);
    assert_eq!(as_f64(&a["q"][0]), -0.5);
    // c = C qd in the output as well.
    let c: Vec<f64> = (0..4)
        .map(|k| {
            (0..4)
                .map(|j| as_f64(&a["coriolis_matrix"][k][j]) * as_f64(&a["qd"][j]))
                .sum()
        })
        .collect();
    for k in 0..4 {
        assert_abs_diff_eq!(c[k], as_f64(&a["coriolis"][k]), epsilon = 1e-12);
    }
}

#[test]
fn bad_number_is_an_error_naming_argument_and_value() {
    assert_fails_with(&["model", "--q", "0,abc,0,0"], &["--q", "abc"]);
    assert_fails_with(&["model", "--qd", "0,0,1.5.2,0"], &["--qd", "1.5.2"]);
    assert_fails_with(&["model", "--q", "0,,0,0"], &["--q"]);
}

#[test]
fn non_finite_numbers_are_errors() {
    assert_fails_with(&["model", "--q", "0,NaN,0,0"], &["--q", "NaN", "finite"]);
    assert_fails_with(&["model", "--qd", "inf,0,0,0"], &["--qd", "inf", "finite"]);
    assert_fails_with(
        &["model", "--qd", "0,0,0,-infinity"],
        &["--qd", "-infinity", "finite"],
    );
}

#[test]
fn wrong_count_is_an_error_naming_robot_and_count() {
    assert_fails_with(
        &["model", "--robot", "scara", "--q", "0,0,0"],
        &["--q", "'0,0,0'", "3 value", "scara", "4 joints"],
    );
    assert_fails_with(
        &["model", "--robot", "puma560", "--qd", "0,0,0,0"],
        &["--qd", "puma560", "6 joints"],
    );
    assert_fails_with(
        &["model", "--robot", "planar2", "--q", "0,0,0"],
        &["--q", "planar2", "2 joints"],
    );
}

#[test]
fn unknown_robot_is_an_error_listing_the_robots() {
    assert_fails_with(
        &["model", "--robot", "kuka"],
        &["--robot", "kuka", "scara", "puma560", "planar2"],
    );
}

#[test]
fn urdf_prints_or_writes_the_generated_urdf_of_every_robot() {
    for &robot in armdyn::model::ROBOTS {
        let output = armdyn(&["urdf", "--robot", robot]);
        assert!(output.status.success(), "{robot}: {}", stderr_of(&output));
        let text = String::from_utf8(output.stdout).expect("UTF-8");
        assert!(text.starts_with("<?xml"), "{robot}: {text}");
        assert!(
            text.contains(&format!("<robot name=\"{robot}\"")),
            "{robot}: robot element"
        );
        let committed = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("generated/urdf")
                .join(format!("{robot}.urdf")),
        )
        .expect("generated/urdf/<robot>.urdf");
        assert_eq!(text, committed, "{robot}: printed URDF vs generated/urdf");
        // `--robot` takes `-` for `_` in every command (here `scara-mdh` for `scara_mdh`).
        let hyphenated = armdyn(&["urdf", "--robot", &robot.replace('_', "-")]);
        assert!(
            hyphenated.status.success(),
            "{robot}: {}",
            stderr_of(&hyphenated)
        );
        assert_eq!(
            hyphenated.stdout,
            text.as_bytes(),
            "{robot}: hyphenated name"
        );
    }
    let dir = tmp("model", "urdf");
    let out = dir.join("scara.urdf");
    let output = armdyn(&["urdf", "--robot", "scara", "--out", out.to_str().unwrap()]);
    assert!(output.status.success(), "{}", stderr_of(&output));
    assert!(output.stdout.is_empty());
    let written = std::fs::read_to_string(&out).unwrap();
    assert!(written.contains("<joint name=\"d3\" type=\"prismatic\">"));
    assert_fails_with(
        &["urdf", "--robot", "kuka"],
        &["--robot", "kuka", "panda", "ur5"],
    );
}
