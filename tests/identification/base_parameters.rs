//! Identification end to end on every robot: base parameter counts checked by an independent
//! rank computation, exact recovery from noise-free data, validation error with 1 % noise,
//! excitation limits, and the identification.json round trip.

use approx::assert_relative_eq;
use nalgebra::{DMatrix, DVector};

use armdyn::identification::excitation::{check_limits, ExcitationLimits};
use armdyn::identification::file::{read_model, to_json};
use armdyn::identification::{
    full_regressor, identify, BaseParameters, Identifiable, IdentifySettings,
};
use armdyn::model::{JointVector, Planar2, Puma560, RobotModel, Scara, ScaraMdh};

use crate::scratch::Scratch;

/// Rank of `w` by nalgebra's SVD after normalising its columns, at relative tolerance `tol`.
fn rank(w: &DMatrix<f64>, tol: f64) -> usize {
    let mut n = w.clone();
    for j in 0..w.ncols() {
        let c = w.column(j).norm();
        if c > 0.0 {
            n.column_mut(j).scale_mut(1.0 / c);
        }
    }
    let scale = n.norm();
    n.svd(false, false).rank(tol * scale)
}

/// Deterministic "random" states other than the ones the selection used.
fn state<const N: usize>(k: usize) -> [JointVector<N>; 3] {
    let f = |i: usize, s: f64| (1.3 * (k * N + i) as f64 + s).sin();
    [
        JointVector::<N>::from_fn(|i, _| f(i, 0.1)),
        JointVector::<N>::from_fn(|i, _| 2.0 * f(i, 0.7)),
        JointVector::<N>::from_fn(|i, _| 3.0 * f(i, 2.1)),
    ]
}

fn check_base<const N: usize, R: Identifiable<N>>(
    robot: &R,
    friction: Option<f64>,
    expected: usize,
) {
    let b = BaseParameters::of_robot(robot, friction, 200, 7).unwrap();
    assert_eq!(b.count(), expected, "{}: {:?}", R::NAME, b.names());
    // An independent check: the full stacked regressor at other states has that rank, and its
    // base columns alone too.
    let p = b.parameter_names().len();
    let mut w = DMatrix::zeros(0, p);
    for k in 0..150 {
        let [q, qd, qdd] = state::<N>(k);
        let y = full_regressor(robot, &q, &qd, &qdd, friction);
        let r = w.nrows();
        w = w.resize_vertically(r + N, 0.0);
        w.view_mut((r, 0), (N, p)).copy_from(&y);
    }
    assert_eq!(rank(&w, 1e-10), expected, "{}", R::NAME);
    assert_eq!(rank(&b.select(&w), 1e-10), expected, "{}", R::NAME);
    // Y_b pi_b = Y pi at those states.
    let mut pi = robot.standard_parameters();
    if friction.is_some() {
        pi = pi.resize_vertically(p, 0.5);
    }
    assert_relative_eq!(
        &w * &pi,
        b.select(&w) * b.project(&pi),
        epsilon = 1e-9,
        max_relative = 1e-10
    );
}

#[test]
fn base_parameter_counts() {
    check_base(&Scara, None, 8);
    check_base(&ScaraMdh, None, 8);
    check_base(&Planar2, None, 6);
    check_base(&Puma560, None, 36);
    // Friction adds two identifiable parameters per joint.
    check_base(&Scara, Some(0.05), 16);
    check_base(&Puma560, Some(0.05), 48);
}

#[test]
fn scara_and_scara_mdh_have_the_same_base_count_and_torques() {
    let a = BaseParameters::of_robot(&Scara, None, 100, 1).unwrap();
    let b = BaseParameters::of_robot(&ScaraMdh, None, 100, 1).unwrap();
    assert_eq!(a.count(), b.count());
    let pa = a.project(&Scara.standard_parameters());
    let pb = b.project(&ScaraMdh.standard_parameters());
    for k in 0..20 {
        let [q, qd, qdd] = state::<4>(k);
        let ta = a.select(&Scara.regressor(&q, &qd, &qdd)) * &pa;
        let tb = b.select(&ScaraMdh.regressor(&q, &qd, &qdd)) * &pb;
        assert_relative_eq!(ta, tb, epsilon = 1e-9);
    }
}

fn run<const N: usize, R: Identifiable<N>>(
    robot: &R,
    noise: f64,
    friction: bool,
) -> armdyn::identification::Identification<N> {
    let mut s = IdentifySettings::new(noise, friction, 1);
    s.excitation.evaluations = 400;
    identify(robot, &s).unwrap()
}

#[test]
fn noise_free_data_recover_the_base_parameters() {
    for friction in [false, true] {
        let id = run(&Scara, 0.0, friction);
        let worst = id.relative_errors.iter().copied().fold(0.0, f64::max);
        assert!(worst < 1e-8, "scara, friction {friction}: {worst:e}");
        let id = run(&Puma560, 0.0, friction);
        let worst = id.relative_errors.iter().copied().fold(0.0, f64::max);
        assert!(worst < 1e-8, "puma560, friction {friction}: {worst:e}");
        assert!(id.consistency.all_ok(), "{}", id.consistency.summary());
    }
}

#[test]
fn one_percent_noise_predicts_validation_torques_within_two_percent() {
    for friction in [false, true] {
        let id = run(&Scara, 1.0, friction);
        assert!(
            id.validation_error_pct.iter().all(|e| *e <= 2.0),
            "scara {friction}: {:?}",
            id.validation_error_pct
        );
        // The error is the noise: against the noise-free torques it is far smaller.
        assert!(
            id.validation_error_noise_free_pct.iter().all(|e| *e < 0.5),
            "{:?}",
            id.validation_error_noise_free_pct
        );
        let id = run(&Puma560, 1.0, friction);
        assert!(
            id.validation_error_pct.iter().all(|e| *e <= 2.0),
            "puma560 {friction}: {:?}",
            id.validation_error_pct
        );
    }
}

#[test]
fn the_excitation_keeps_to_the_limits_and_improves_the_conditioning() {
    let id = run(&Puma560, 1.0, false);
    let limits = ExcitationLimits::default_for::<Puma560>();
    assert_eq!(
        check_limits::<6, Puma560>(&id.excitation.trajectory, &limits),
        None
    );
    assert!(id.excitation.condition_number <= id.excitation.initial_condition_number);
    assert!(id
        .excitation
        .peak_effort_fraction
        .iter()
        .all(|e| *e <= limits.effort_fraction));
    // Noise is the stated percentage of each joint's RMS torque.
    let m = &id.measurement;
    for i in 0..6 {
        let rms = armdyn::identification::measurement::rms(&m.tau_true, i);
        assert_relative_eq!(m.noise_std[i], 0.01 * rms, max_relative = 1e-12);
    }
}

#[test]
fn identification_json_round_trip_and_errors() {
    let id = run(&Scara, 1.0, true);
    let v = to_json(&id);
    for key in [
        "robot",
        "base_parameter_count",
        "base_parameter_names",
        "base_parameters_true",
        "base_parameters_estimated",
        "relative_errors",
        "condition_number",
        "validation_torque_rms_error_pct",
    ] {
        assert!(v.get(key).is_some(), "{key}");
    }
    let dir = Scratch::new("identification-file");
    let path = dir.join("identification.json");
    std::fs::write(&path, serde_json::to_string(&v).unwrap()).unwrap();
    let model = read_model(&path, Scara).unwrap();
    // The model read back gives the estimate's torques (friction aside).
    let est = DVector::from_column_slice(id.estimate.weighted.as_slice());
    for k in 0..10 {
        let [q, qd, qdd] = state::<4>(k);
        let y = full_regressor(&Scara, &q, &qd, &qdd, Some(0.05));
        let mut rigid = id.base.select(&y);
        let friction_cols: Vec<usize> = id
            .base
            .independent()
            .iter()
            .enumerate()
            .filter(|(_, j)| **j >= 40)
            .map(|(i, _)| i)
            .collect();
        for c in friction_cols {
            rigid.column_mut(c).fill(0.0);
        }
        assert_relative_eq!(
            model.inverse_dynamics(&q, &qd, &qdd),
            JointVector::<4>::from_iterator((rigid * &est).iter().copied()),
            epsilon = 1e-9
        );
    }
    let bad = |text: &str, needle: &str| {
        std::fs::write(&path, text).unwrap();
        let e = read_model(&path, Scara).unwrap_err().to_string();
        assert!(
            e.contains("identification.json") && e.contains(needle),
            "{e}"
        );
    };
    bad("{", "not JSON");
    bad(r#"{"robot": "puma560"}"#, "`robot`");
    bad(
        r#"{"robot": "scara", "parameter_names": []}"#,
        "`base_parameter_indices`",
    );
    bad(
        r#"{"robot": "scara", "parameter_names": ["m1"], "base_parameter_indices": [0, 1], "base_parameters_estimated": [1.0]}"#,
        "must match",
    );
    bad(
        r#"{"robot": "scara", "parameter_names": ["m1"], "base_parameter_indices": [5], "base_parameters_estimated": [1.0]}"#,
        "`base_parameter_indices[0]`",
    );
    bad(
        r#"{"robot": "scara", "parameter_names": ["m1"], "base_parameter_indices": [0], "base_parameters_estimated": ["x"]}"#,
        "`base_parameters_estimated[0]`",
    );
    bad(
        r#"{"robot": "scara", "parameter_names": ["m1", "m2"], "base_parameter_indices": [1, 1], "base_parameters_estimated": [1.0, 2.0]}"#,
        "appears twice",
    );
}
