//! Gains computed from the model as the thesis does (docs/thesis.md section 4), the pole-placement
//! design's closed-loop eigenvalues and the LQR Riccati residual.

use approx::abs_diff_eq;
use armdyn::control::fsf::{FullStateFeedback, LqrWeights};
use armdyn::control::gains::{MassRounding, PidGains};
use armdyn::control::mass_split::{constant_part, SplitKind};
use armdyn::control::pid_fl::PidFeedbackLinearization;
use armdyn::model::{RobotModel, Scara};
use armdyn::robots::scara::thesis_setup::THESIS_FSF_POLES;
use armdyn::robots::scara::thesis_setup::THESIS_PID_POLES;
use nalgebra::{DMatrix, Vector4};

/// Printed gains must be matched to 0.1 % (issue acceptance).
const GAIN_REL_TOL: f64 = 1e-3;
/// Eigenvalues of the placement design, absolute, rad/s.
const POLE_TOL: f64 = 1e-9;
/// Relative Riccati residual.
const RICCATI_TOL: f64 = 1e-10;

fn assert_rel(name: &str, got: &Vector4<f64>, want: [f64; 4]) {
    for i in 0..4 {
        let rel = (got[i] - want[i]).abs() / want[i].abs();
        assert!(
            rel <= GAIN_REL_TOL,
            "{name}[{i}]: got {}, thesis {} ({:.3} %)",
            got[i],
            want[i],
            rel * 100.0
        );
    }
}

#[test]
fn decentralized_pid_gains_match_eq_4_15() {
    let mut q = Vector4::zeros();
    q[1] = 0.0; // fully extended, as the thesis's linearization (eq. 4.2)
    let masses = MassRounding::Thesis.apply(&Scara.mass_matrix(&q).diagonal());
    let g = PidGains::from_poles(&masses, THESIS_PID_POLES);
    assert_rel("Kp", &g.kp, [1347.94, 271.04, 1195.48, 0.605]);
    assert_rel("Ki", &g.ki, [4010.4, 806.4, 3556.8, 1.8]);
    assert_rel("Kd", &g.kd, [150.39, 30.24, 133.38, 0.0675]);
}

#[test]
fn feedback_linearization_gains_match_eq_4_22() {
    for kind in [SplitKind::ConstantPart, SplitKind::ConstantDiagonal] {
        let c = PidFeedbackLinearization::with_poles(
            Scara,
            kind,
            MassRounding::Thesis,
            THESIS_PID_POLES,
        )
        .unwrap();
        let g = c.gains();
        assert_rel("Kp2", &g.kp, [781.66, 271.04, 1195.48, 0.605]);
        assert_rel("Ki2", &g.ki, [2325.6, 806.4, 3556.8, 1.8]);
        assert_rel("Kd2", &g.kd, [87.21, 30.24, 133.38, 0.0675]);
    }
}

#[test]
fn constant_part_of_m_is_eq_4_18() {
    let m = constant_part(&Scara);
    let printed = [
        [3.23, 1.12, 0.0, -0.0025],
        [1.12, 1.12, 0.0, -0.0025],
        [0.0, 0.0, 4.94, 0.0],
        [-0.0025, -0.0025, 0.0, 0.0025],
    ];
    for r in 0..4 {
        for k in 0..4 {
            assert!(
                abs_diff_eq!(m[(r, k)], printed[r][k], epsilon = 0.005),
                "M_linear[{r}][{k}] = {}",
                m[(r, k)]
            );
        }
    }
}

fn sorted_eigenvalues(a: &DMatrix<f64>) -> Vec<(f64, f64)> {
    let mut ev: Vec<(f64, f64)> = a
        .clone()
        .complex_eigenvalues()
        .iter()
        .map(|z| (z.re, z.im))
        .collect();
    ev.sort_by(|x, y| x.0.total_cmp(&y.0));
    ev
}

#[test]
fn pole_placement_gives_the_requested_poles() {
    let c = FullStateFeedback::place(Scara, &THESIS_FSF_POLES).unwrap();
    let ev = sorted_eigenvalues(&c.closed_loop_matrix());
    let mut want = THESIS_FSF_POLES.to_vec();
    want.sort_by(f64::total_cmp);
    for ((re, im), p) in ev.iter().zip(&want) {
        assert!(
            abs_diff_eq!(*re, *p, epsilon = POLE_TOL) && abs_diff_eq!(*im, 0.0, epsilon = POLE_TOL),
            "eigenvalue {re}+{im}i, wanted {p}"
        );
    }
    // The third row of K acts on d3 alone (the coupling the thesis's place() result had,
    // eq. 4.34-4.35, is gone).
    for j in [0, 1, 3] {
        assert_eq!(c.k1()[(2, j)], 0.0);
        assert_eq!(c.k2()[(2, j)], 0.0);
    }
}

#[test]
fn pole_placement_rejects_bad_poles() {
    assert!(FullStateFeedback::place(Scara, &[-1.0; 7]).is_err());
    let mut p = THESIS_FSF_POLES;
    p[3] = 0.5;
    assert!(FullStateFeedback::place(Scara, &p).is_err());
    p[3] = f64::NAN;
    assert!(FullStateFeedback::place(Scara, &p).is_err());
}

#[test]
fn lqr_gain_satisfies_the_riccati_equation() {
    let m_lin = constant_part(&Scara);
    let (c, sol) = FullStateFeedback::lqr(
        Scara,
        &LqrWeights::acceleration_penalty(&m_lin, 8.35).unwrap(),
    )
    .unwrap();
    assert!(sol.residual <= RICCATI_TOL, "residual {}", sol.residual);
    // Critically damped at -8.35 on every joint, as designed.
    for (re, im) in sorted_eigenvalues(&c.closed_loop_matrix()) {
        assert!(
            abs_diff_eq!(re, -8.35, epsilon = 1e-4) && abs_diff_eq!(im, 0.0, epsilon = 1e-4),
            "{re} {im}"
        );
    }
}

#[test]
#[allow(clippy::needless_range_loop)] // i, j index three matrices at once
fn thesis_lqr_weights_reproduce_eq_4_36() {
    // Q = I, R = I on the plant with the thesis's rounded M_linear (eq. 4.18).
    let m_lin = nalgebra::Matrix4::new(
        3.23, 1.12, 0.0, -0.0025, 1.12, 1.12, 0.0, -0.0025, 0.0, 0.0, 4.94, 0.0, -0.0025, -0.0025,
        0.0, 0.0025,
    );
    let (a, b) = armdyn::control::fsf::linearized_plant(&m_lin).unwrap();
    let w = LqrWeights::identity(4);
    let sol = armdyn::control::lqr::lqr(&a, &b, &w.q, &w.r).unwrap();
    assert!(sol.residual <= RICCATI_TOL, "residual {}", sol.residual);
    let printed_k2 = [
        [2.6837, 0.5078, 0.0, -0.0011],
        [0.5078, 1.7268, 0.0, -0.0016],
        [0.0, 0.0, 3.2987, 0.0],
        [-0.0011, -0.0016, 0.0, 1.0025],
    ];
    for i in 0..4 {
        for j in 0..4 {
            let want_k1 = if i == j { 1.0 } else { 0.0 };
            assert!(
                abs_diff_eq!(sol.k[(i, j)], want_k1, epsilon = 5e-4),
                "K1[{i}][{j}] = {}",
                sol.k[(i, j)]
            );
            assert!(
                abs_diff_eq!(sol.k[(i, 4 + j)], printed_k2[i][j], epsilon = 5e-4),
                "K2[{i}][{j}] = {}",
                sol.k[(i, 4 + j)]
            );
        }
    }
}
