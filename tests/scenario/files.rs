//! The scenario reader: every rule refused with the file, the key (and line) and the rule,
//! before anything runs and with nothing written; random and mutated files never panic.

use std::path::{Path, PathBuf};

use crate::command::{armdyn, s, stderr};
use crate::properties::config;
use crate::scratch::Scratch;

use approx::{abs_diff_eq, assert_abs_diff_eq};
use armdyn::scenario::{prepare, Scenario, ScenarioError, BUILT_IN};
use proptest::prelude::*;

fn shipped(file: &str) -> String {
    std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("scenarios")
            .join(file),
    )
    .unwrap()
}

fn parse(text: &str) -> Result<Scenario, ScenarioError> {
    Scenario::parse("test.toml", text, Path::new("."))
}

/// Parses and prepares `text`; the error must name `key` and contain `rule`.
fn refused(text: &str, key: &str, rule: &str) -> ScenarioError {
    let e = match parse(text) {
        Err(e) => e,
        Ok(s) => match prepare(&s) {
            Err(e) => e,
            Ok(_) => panic!("accepted; expected `{key}`: {rule}"),
        },
    };
    assert_eq!(e.file, "test.toml");
    assert_eq!(e.key, key, "{e}");
    assert!(e.rule.contains(rule), "{e}");
    e
}

#[test]
fn unknown_keys_and_wrong_types_name_the_key_and_line() {
    let base = shipped("oblique-plane.toml");
    let t = base.replace("stiffness = 10000.0", "stiffness = 10000.0\nstifness = 1.0");
    let e = refused(&t, "surfaces[0].stifness", "unknown field `stifness`");
    assert_eq!(
        e.line,
        Some(t.lines().position(|l| l.starts_with("stifness")).unwrap() + 1)
    );
    let t = base.replace("stiffness = 10000.0", "stiffness = \"10 kN/m\"");
    let e = refused(&t, "surfaces[0].stiffness", "invalid type: string");
    assert!(e.to_string().starts_with("test.toml:"), "{e}");
    refused(
        &base.replace("[position]", "[positon]"),
        "positon",
        "unknown field",
    );
}

#[test]
fn every_force_law_setting_out_of_range_is_refused_with_its_unit() {
    let base = shipped("oblique-plane.toml");
    let design = "bandwidth_hz = 10.0\ndamping = 1.0\n";
    for (table, given, key, rule) in [
        (
            "design",
            "bandwidth_hz = 0.0\ndamping = 1.0",
            "bandwidth_hz",
            "a frequency in Hz, > 0 and <= 1e4",
        ),
        (
            "design",
            "bandwidth_hz = 10.0\ndamping = 101.0",
            "damping",
            "a damping ratio, > 0 and <= 1e2",
        ),
        (
            "design",
            &format!("{design}integral_hz = -1.0"),
            "integral_hz",
            "a frequency in Hz, > 0 and <= 1e4",
        ),
        (
            "design",
            &format!("{design}stiffness = 2e9"),
            "stiffness",
            "a stiffness in N/m, > 0 and <= 1e9",
        ),
        (
            "impedance",
            "stiffness = -1.0",
            "stiffness",
            "a stiffness in N/m, > 0 and <= 1e9",
        ),
        (
            "impedance",
            "damping_ratio = 0.0",
            "damping_ratio",
            "a damping ratio, > 0 and <= 1e2",
        ),
        (
            "impedance",
            "tangential_stiffness = 0.0",
            "tangential_stiffness",
            "a stiffness in N/m",
        ),
        (
            "impedance",
            "yaw_stiffness = -5.0",
            "yaw_stiffness",
            "a stiffness in N m/rad, > 0 and <= 1e9",
        ),
        (
            "impedance",
            "tilt_stiffness = 2e9",
            "tilt_stiffness",
            "a stiffness in N m/rad",
        ),
        (
            "impedance",
            "contact_stiffness = 0.0",
            "contact_stiffness",
            "a stiffness in N/m",
        ),
        (
            "admittance",
            "mass = 0.0",
            "mass",
            "a mass in kg, > 0 and <= 1e6",
        ),
        (
            "admittance",
            "damping = 2e9",
            "damping",
            "a damping in N s/m, > 0 and <= 1e9",
        ),
    ] {
        let text = format!("{base}\n[force.{table}]\n{given}\n");
        refused(&text, &format!("force.{table}.{key}"), rule);
    }
}

#[test]
fn values_out_of_range_or_sign_are_refused() {
    let base = shipped("oblique-plane.toml");
    refused(
        &base.replace("stiffness = 10000.0", "stiffness = -10000.0"),
        "surfaces[0].stiffness",
        "> 0",
    );
    refused(
        &base.replace("value = 200.0", "value = -200.0"),
        "force.value",
        "> 0",
    );
    refused(
        &base.replace("value = 200.0", "value = 200000.0"),
        "force.value",
        "wrong unit",
    );
    refused(
        &base.replace("control_dt_s = 0.001", "control_dt_s = 1.0"),
        "control_dt_s",
        "in ms?",
    );
    refused(
        &base.replace("debounce_s = 0.003", "debounce_s = -0.003"),
        "selection.debounce_s",
        ">= 0",
    );
    refused(
        &base.replace("q0 = [0.0, 0.0, 0.1, 0.0]", "q0 = [0.0, 0.0, 0.0, 0.0]"),
        "q0",
        "outside its limits",
    );
    refused(
        &base.replace("format = 1", "format = 2"),
        "format",
        "format 2 is not known",
    );
}

#[test]
fn the_controllers_armature_is_one_inertia_per_joint_and_not_negative() {
    let base = shipped("oblique-plane.toml");
    let with = |a: &str| {
        base.replace(
            "robot = \"scara\"",
            &format!("robot = \"scara\"\ncontroller_armature = {a}"),
        )
    };
    refused(
        &with("[0.1, 0.1, 0.1]"),
        "controller_armature",
        "needs 4 values",
    );
    refused(
        &with("[0.1, -0.1, 0.1, 0.1]"),
        "controller_armature",
        "joint 2: -0.1 is negative",
    );
    let s = parse(&with("[0.1, 0.2, 0.3, 0.4]")).unwrap();
    assert_eq!(s.controller_armature, Some(vec![0.1, 0.2, 0.3, 0.4]));
    assert!(prepare(&s)
        .unwrap()
        .gains
        .note
        .contains("armature [0.1, 0.2, 0.3, 0.4]"));
}

#[test]
fn a_zero_normal_is_refused_and_a_long_one_normalised() {
    let base = shipped("oblique-plane.toml");
    let i = base.find("normal = [").unwrap();
    let j = base[i..].find(']').unwrap() + i + 1;
    let with = |n: &str| format!("{}normal = {n}{}", &base[..i], &base[j..]);
    refused(&with("[0.0, 0.0, 0.0]"), "surfaces[0].normal", "is zero");
    let a = 20_f64.to_radians();
    let s = parse(&with(&format!(
        "[{}, 0.0, {}]",
        3.0 * a.sin(),
        3.0 * a.cos()
    )))
    .unwrap();
    let original = parse(&base).unwrap();
    let (
        armdyn::contact::SurfaceGeometry::Plane(armdyn::contact::Plane { normal: n, .. }),
        armdyn::contact::SurfaceGeometry::Plane(armdyn::contact::Plane { normal: m, .. }),
    ) = (s.surfaces[0].geometry, original.surfaces[0].geometry)
    else {
        panic!("planes")
    };
    assert_abs_diff_eq!((n - m).norm(), 0.0, epsilon = 1e-15);
    assert_abs_diff_eq!(n.norm(), 1.0, epsilon = 1e-15);
}

#[test]
fn kind_specific_keys_are_checked() {
    let base = shipped("sphere-patch.toml");
    refused(
        &base.replace("radius = 1.0", "radius = 1.0\nnormal = [0.0, 0.0, 1.0]"),
        "surfaces[0].normal",
        "does not belong",
    );
    refused(
        &base.replace("radius = 1.0\n", ""),
        "surfaces[0].radius",
        "is missing",
    );
    refused(
        &base.replace("kind = \"sphere\"", "kind = \"cone\""),
        "surfaces[0].kind",
        "known: plane, sphere, cylinder",
    );
    refused(
        &base.replace("mode = \"contact\"", "mode = \"time\""),
        // The first of the contact mode's keys in the table's (alphabetical) order.
        "selection.approach_speed_m_s",
        "mode = \"contact\"",
    );
    refused(
        &base.replace("mode = \"contact\"", "mode = \"contact\"\ntreshold_n = 5.0"),
        "selection.treshold_n",
        "unknown field `treshold_n`: mode = \"contact\" takes `threshold_n`, `debounce_s`",
    );
    refused(
        &base.replace("law = \"pid-fl\"", "law = \"pid-fl\"\ndamping_ratio = 1.0"),
        "position.damping_ratio",
        "does not belong here: a key of law = \"task-space\"",
    );
    refused(
        &base.replace(
            "law = \"pid-fl\"",
            "law = \"pid-fl\"\nacceleration_feedforward = 1",
        ),
        "position.acceleration_feedforward",
        "invalid type: integer, expected true or false",
    );
    refused(
        &base.replace("law = \"pid-fl\"", "law = \"pid-fl\"\nfeedforward = true"),
        "position.feedforward",
        "unknown field `feedforward`: law = \"pid-fl\" takes `acceleration_feedforward`",
    );
    refused(
        &base.replace("interpolation = \"linear\"", "interpolation = \"cubic\""),
        "reference.interpolation",
        "known: linear, quintic",
    );
    refused(
        &base.replace(
            "kind = \"waypoints\"",
            "kind = \"waypoints\"\nfile = \"poses.csv\"",
        ),
        "reference.file",
        "not a key of kind = \"waypoints\"",
    );
    refused(
        &base.replace("kind = \"waypoints\"", "kind = \"spline\""),
        "reference.kind",
        "unknown kind `spline`; known: thesis, waypoints, csv, joints",
    );
    let csv = base
        .replace(
            "kind = \"waypoints\"",
            "kind = \"csv\"\nfile = \"poses.csv\"",
        )
        .replace("interpolation = \"linear\"\n", "");
    refused(&csv, "reference.points", "not a key of kind = \"csv\"");
    refused(
        &csv.replace("points = ", "name = \"contact\"\npoints = "),
        "reference.name",
        "not a key of kind = \"csv\"",
    );
    let thesis = shipped("thesis-hybrid.toml").replace(
        "kind = \"thesis\"",
        "kind = \"thesis\"\ninterpolation = \"linear\"",
    );
    refused(
        &thesis,
        "reference.interpolation",
        "not a key of kind = \"thesis\"",
    );
}

#[test]
fn a_surface_the_reference_never_reaches_and_a_reference_outside_the_workspace() {
    let base = shipped("oblique-plane.toml");
    let e = refused(
        &base.replace("point = [0.5, 0.0, 0.13]", "point = [0.5, 0.0, 0.03]"),
        "surfaces[0]",
        "never reaches this surface",
    );
    assert!(e.line.is_some(), "{e}");
    refused(
        &base.replace("[10.0, 0.5, 0.3, 0.13, 0.0]", "[10.0, 0.9, 0.3, 0.13, 0.0]"),
        "reference",
        "leaves the workspace",
    );
}

#[test]
fn the_command_line_checks_before_running_and_writes_nothing_on_error() {
    let dir = Scratch::new("scenario-files-check");
    let good = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/unknown-height.toml");
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        shipped("unknown-height.toml").replace("stiffness = 10000.0", "stiffness = 0.0"),
    )
    .unwrap();
    let out = dir.join("out");
    let o = armdyn(&["run", "scenario", s(&good), s(&bad), "--out", s(&out)]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("bad.toml:") && err.contains("`surfaces[0].stiffness`"),
        "{err}"
    );
    assert!(
        !out.exists(),
        "the good file ran although the bad one was refused"
    );
    let o = armdyn(&["run", "scenario", "--check", s(&good)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("ok (unknown-height)"));
    let o = armdyn(&["run", "scenario", s(&good), "--out", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in [
        "metrics.json",
        "trajectory.csv",
        "path.svg",
        "normal_force.svg",
        "force.svg",
    ] {
        assert!(out.join(f).is_file(), "missing {f}");
    }
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("metrics.json")).unwrap()).unwrap();
    for key in [
        "normal_force_overshoot_pct",
        "normal_force_settling_time_s",
        "normal_force_rms_error_last5s_n",
        "path_rms_error_contact_mm",
        "first_touch_s",
        "contact_detected_s",
        "peak_normal_force_n",
        "saturated_samples",
        "end_stop_samples",
        "max_tangential_force_n",
        "force_overshoot_pct",
        "max_joint_error_after_2s",
    ] {
        assert!(m.get(key).is_some(), "metrics.json lacks {key}");
    }
}

/// One edit of a text: delete a range, insert a token, or replace a number.
#[derive(Clone, Debug)]
enum Mutation {
    Delete(usize, usize),
    Insert(usize, String),
    Number(usize, String),
}

fn mutate(text: &str, m: &Mutation) -> String {
    let at = |i: usize| {
        let mut i = i % (text.len() + 1);
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    match m {
        Mutation::Delete(a, n) => {
            let a = at(*a);
            let b = at(a + n % 40);
            format!("{}{}", &text[..a], &text[b.max(a)..])
        }
        Mutation::Insert(a, s) => {
            let a = at(*a);
            format!("{}{s}{}", &text[..a], &text[a..])
        }
        Mutation::Number(k, s) => {
            let numbers: Vec<usize> = text
                .match_indices(|c: char| c.is_ascii_digit())
                .map(|(i, _)| i)
                .collect();
            if numbers.is_empty() {
                return text.to_string();
            }
            let i = numbers[k % numbers.len()];
            let end = text[i..]
                .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == '-'))
                .map_or(text.len(), |e| i + e);
            format!("{}{s}{}", &text[..i], &text[end..])
        }
    }
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let token = prop_oneof![
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("-1e308".to_string()),
        Just("1e400".to_string()),
        Just("\"x\"".to_string()),
        Just("[]".to_string()),
        Just("[[surfaces]]\n".to_string()),
        Just("\n[force]\n".to_string()),
        Just("0".to_string()),
        Just("-0.0".to_string()),
        "[ -~]{0,12}",
    ];
    prop_oneof![
        (any::<usize>(), any::<usize>()).prop_map(|(a, n)| Mutation::Delete(a, n)),
        (any::<usize>(), token.clone()).prop_map(|(a, s)| Mutation::Insert(a, s)),
        (any::<usize>(), token).prop_map(|(k, s)| Mutation::Number(k, s)),
    ]
}

proptest! {
    #![proptest_config(config(192, 21))]

    #[test]
    fn mutated_scenarios_never_panic_and_errors_name_a_key_or_line(
        which in 0..BUILT_IN.len() + 5,
        edits in proptest::collection::vec(mutation(), 1..4),
    ) {
        let extra = ["oblique-plane.toml", "sphere-patch.toml", "friction.toml", "unknown-height.toml", "friction-without-feedforward.toml"];
        let mut text = if which < BUILT_IN.len() { BUILT_IN[which].1.to_string() } else { shipped(extra[which - BUILT_IN.len()]) };
        for m in &edits {
            text = mutate(&text, m);
        }
        let result = parse(&text).and_then(|s| prepare(&s).map(|_| ()));
        if let Err(e) = result {
            prop_assert_eq!(&e.file, "test.toml");
            prop_assert!(!e.key.is_empty() || e.line.is_some(), "neither key nor line: {}", e);
            prop_assert!(!e.rule.is_empty());
        }
    }

    #[test]
    fn random_text_never_panics(text in "[ -~\n]{0,400}") {
        if let Err(e) = parse(&text) {
            prop_assert!(!e.rule.is_empty());
        }
    }
}

proptest! {
    #![proptest_config(config(256, 22))]

    /// The force-reference CSV reader (`[force] reference = "csv"`): random and mutated text,
    /// a byte-order mark, CRLF, never a panic, errors that name a line.
    #[test]
    fn force_csv_never_panics_and_names_the_line(
        bom in any::<bool>(),
        crlf in any::<bool>(),
        rows in proptest::collection::vec((0.0..10.0f64, 0.0..500.0f64), 0..6),
        junk in "[ -~\n]{0,30}",
        at in any::<usize>(),
    ) {
        use armdyn::trajectory::force_csv::SampledForce;
        let nl = if crlf { "\r\n" } else { "\n" };
        let mut text = String::from(if bom { "\u{feff}t,f" } else { "t,f" });
        let mut t = 0.0;
        for (dt, f) in &rows {
            t += dt + 1e-3;
            text.push_str(&format!("{nl}{t},{f}"));
        }
        match SampledForce::from_csv_reader(text.as_bytes()) {
            Ok(s) => prop_assert!(
                rows.len() >= 2 && abs_diff_eq!(s.at(t), rows[rows.len() - 1].1, epsilon = 1e-9)
            ),
            Err(e) => prop_assert!(rows.len() < 2, "{}", e),
        }
        let mut cut = at % (text.len() + 1);
        while !text.is_char_boundary(cut) {
            cut -= 1;
        }
        let mutated = format!("{}{junk}{}", &text[..cut], &text[cut..]);
        if let Err(e) = SampledForce::from_csv_reader(mutated.as_bytes()) {
            let m = e.to_string();
            prop_assert!(m.contains("line") || m.contains("row") || m.contains("read"), "{}", m);
        }
    }
}
