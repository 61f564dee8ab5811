//! The generated Jaco2 against Pinocchio on the same URDF (`description/kinova.urdf`): the
//! mass matrix, `c + g` and forward dynamics at 64 random states, to 1e-9 relative
//! (`tests/pinocchio_reference.py` computes Pinocchio's side; `pip install pin`). Without
//! Pinocchio the test says so and passes, unless `CI` is set: then it fails.

use std::process::Command;

use armdyn::model::RobotModel;
use armdyn::nalgebra::SVector;
use own_robot::Jaco2;
use serde_json::Value;

const TOLERANCE: f64 = 1e-9;

fn vector(v: &Value) -> SVector<f64, 6> {
    SVector::from_iterator(v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
}

/// `|got - want|_max / max(1, |want|_max)`.
fn relative(got: &[f64], want: &[f64]) -> f64 {
    let scale = want.iter().fold(1.0_f64, |a, x| a.max(x.abs()));
    got.iter()
        .zip(want)
        .fold(0.0_f64, |a, (g, w)| a.max((g - w).abs()))
        / scale
}

#[test]
fn mass_matrix_bias_and_forward_dynamics_equal_pinocchio() {
    let dir = env!("CARGO_MANIFEST_DIR");
    let output = Command::new("python3")
        .arg(format!("{dir}/tests/pinocchio_reference.py"))
        .arg("64")
        .output();
    let output = match output {
        Ok(o) if o.status.success() => o,
        other => {
            let why = match other {
                Ok(o) => String::from_utf8_lossy(&o.stderr).into_owned(),
                Err(e) => e.to_string(),
            };
            assert!(
                std::env::var_os("CI").is_none(),
                "Pinocchio's reference could not be computed (pip install pin): {why}"
            );
            eprintln!("skipped: Pinocchio's reference could not be computed: {why}");
            return;
        }
    };
    let states: Vec<Value> = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(states.len(), 64);
    let mut worst = [0.0_f64; 3];
    for s in &states {
        let (q, qd, tau) = (vector(&s["q"]), vector(&s["qd"]), vector(&s["tau"]));
        let (m, bias) = Jaco2.mass_matrix_and_bias(&q, &qd);
        let qdd = Jaco2.forward_dynamics(&q, &qd, &tau).unwrap();
        let m_rows: Vec<f64> = (0..6)
            .flat_map(|i| (0..6).map(move |j| (i, j)))
            .map(|(i, j)| m[(i, j)])
            .collect();
        let want = |k: &str| -> Vec<f64> {
            s[k].as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        };
        let errors = [
            relative(&m_rows, &want("m")),
            relative(bias.as_slice(), &want("bias")),
            relative(qdd.as_slice(), &want("qdd")),
        ];
        for (w, e) in worst.iter_mut().zip(errors) {
            *w = w.max(e);
        }
    }
    println!(
        "jaco2 against Pinocchio, 64 states, largest relative difference: M {:.1e}, c + g {:.1e}, forward dynamics {:.1e}",
        worst[0], worst[1], worst[2]
    );
    for (what, w) in ["M", "c + g", "forward dynamics"].iter().zip(worst) {
        assert!(
            w <= TOLERANCE,
            "{what} differs from Pinocchio by {w:.2e} (relative)"
        );
    }
}
