//! Tests of `armdyn::trajectory::joint_csv`: the joint reference: its cubic spline reproduces a
//! smooth signal, a plan is read with its velocities and passes through its states, a bad file is
//! refused by line and column.

use armdyn::trajectory::joint_csv::*;
use nalgebra::Vector1;

#[test]
fn a_cubic_spline_reproduces_a_smooth_signal() {
    let t: Vec<f64> = (0..=200).map(|k| k as f64 * 0.01).collect();
    let q: Vec<Vector1<f64>> = t.iter().map(|&x| Vector1::new(x.sin())).collect();
    let r = JointReference::<1>::new(t, q).unwrap();
    for k in 1..100 {
        let x = 0.3 + k as f64 * 0.0137;
        let target = r.at(x);
        assert!((target.q[0] - x.sin()).abs() < 1e-8);
        assert!((target.qd[0] - x.cos()).abs() < 1e-5);
        assert!((target.qdd[0] + x.sin()).abs() < 1e-3);
    }
}

#[test]
fn a_plan_is_read_with_its_velocities_and_passes_through_its_states() {
    // q = t^3 sampled with its velocity: the Hermite interval reproduces the cubic.
    let mut text = String::from("t,q_a,q_b,qd_a,qd_b,qdd_a,qdd_b,tau_a,tau_b\n");
    for k in 0..=10 {
        let t = k as f64 * 0.1;
        text += &format!(
            "{t},{},{},{},{},0,0,0,0\n",
            t * t * t,
            -t,
            3.0 * t * t,
            -1.0
        );
    }
    let r = JointReference::<2>::from_csv_reader_named(text.as_bytes(), &["a", "b"]).unwrap();
    for x in [0.05, 0.37, 0.999] {
        let target = r.at(x);
        assert!((target.q[0] - x * x * x).abs() < 1e-12);
        assert!((target.qd[0] - 3.0 * x * x).abs() < 1e-12);
        assert!((target.qdd[0] - 6.0 * x).abs() < 1e-9);
        assert!((target.q[1] + x).abs() < 1e-12 && (target.qd[1] + 1.0).abs() < 1e-12);
    }
    // Other names, or no names: the header is refused, naming both forms.
    let e = JointReference::<2>::from_csv_reader_named(text.as_bytes(), &["x", "y"])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`t,q1,q2` or a plan's `t,q_x,q_y,qd_x,qd_y,...`"),
        "{e}"
    );
    assert!(JointReference::<2>::from_csv_reader(text.as_bytes()).is_err());
}

#[test]
fn bad_files_name_line_and_column() {
    let bad = |text: &str| JointReference::<2>::from_csv_reader(text.as_bytes()).unwrap_err();
    assert!(matches!(bad("t,q1\n0,1\n"), CsvError::Header { .. }));
    let e = bad("t,q1,q2\n0,0,0\n1,0,x\n");
    assert_eq!(
        e.to_string(),
        "line 3, column 3 (`q2`): `x` is not a number"
    );
    assert!(matches!(
        bad("t,q1,q2\n0,0,0\n0,1,1\n"),
        CsvError::NotIncreasing { line: 3, .. }
    ));
    assert!(matches!(
        bad("t,q1,q2\n0,0,0\n"),
        CsvError::TooFewRows { rows: 1, min: 2 }
    ));
    assert!(matches!(
        bad("t,q1,q2\n\n0.5,0,0\n1,0,0\n"),
        CsvError::StartNotZero { line: 3, .. }
    ));
    assert!(bad("t,q1,q2\n0,0,0\n1,0,inf\n").to_string().contains("q2"));
}
