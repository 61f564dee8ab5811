//! The hybrid force/position trial of Chapter 5 and the sign conventions it rests on.

#[allow(dead_code)]
use crate::trials;

use approx::{abs_diff_eq, assert_abs_diff_eq};
use armdyn::contact::Environment;
use armdyn::control::force::ForcePi;
use armdyn::control::hybrid::{HybridForcePosition, JacobianSolve};
use armdyn::control::task_frame::TaskFrame;
use armdyn::control::{Controller, ControllerInput};
use armdyn::model::{external_joint_torque, forward_dynamics, RobotModel, Scara, Wrench};
use armdyn::robots::scara::presets::{ForceReference, HybridSetup, THESIS_FORCE_LAWS};
use armdyn::robots::scara::{Elbow, ScaraGeometry};
use armdyn::scenario::ForceController;
use armdyn::target::CartesianTarget;
use armdyn::target::JointTarget;
use nalgebra::{Vector3, Vector4};

/// Tolerance of exact algebraic identities.
const EXACT: f64 = 1e-9;

/// A SCARA configuration with the tool `depth` m below the thesis surface at (0.45, -0.1).
fn pressing(depth: f64) -> Vector4<f64> {
    let ik = ScaraGeometry::from_model(&Scara);
    ik.inverse(&Vector3::new(0.45, -0.1, 0.13 - depth), 0.0, Elbow::Up)
        .unwrap()
}

#[test]
fn contact_force_pushes_the_tool_back_through_j_transpose() {
    let q = pressing(0.01);
    let surface = armdyn::robots::scara::thesis_setup::thesis_surface();
    let pose = Scara.end_effector_pose(&q);
    let f = surface.wrench(
        &Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]),
        &Vector3::zeros(),
    );
    // The tool exerts 100 N downward on the surface (eq. 5.1, f_ext negative z).
    assert!(abs_diff_eq!(f[2], -100.0, epsilon = 1e-6), "{f}");
    let tau_ext = external_joint_torque(&Scara, &q, &f);
    // J^T f_ext acts on d3 only, opposing further insertion (d3 grows downward).
    assert_abs_diff_eq!(tau_ext[2], 100.0, epsilon = 1e-6);
    assert_abs_diff_eq!(tau_ext.fixed_rows::<2>(0).norm(), 0.0, epsilon = EXACT);
    // Holding gravity alone, the surface accelerates the tool up (d3 decreasing)...
    let qd = Vector4::zeros();
    let qdd = forward_dynamics(&Scara, &q, &qd, &Scara.gravity(&q), &tau_ext).unwrap();
    assert!(qdd[2] < -1.0, "{qdd}");
    // ...and tau = g + J^T f_ext holds it still (thesis eq. 3.66 with erratum 3).
    let qdd = forward_dynamics(&Scara, &q, &qd, &(Scara.gravity(&q) + tau_ext), &tau_ext).unwrap();
    assert!(abs_diff_eq!(qdd.norm(), 0.0, epsilon = EXACT), "{qdd}");
}

struct Fixed(Vector4<f64>);

impl Controller<4> for Fixed {
    fn name(&self) -> &'static str {
        "fixed"
    }
    fn reset(&mut self) {}
    fn step(&mut self, _: &ControllerInput<'_, 4>, _: f64) -> Vector4<f64> {
        self.0
    }
}

#[test]
fn selection_maps_position_and_force_commands_as_eq_5_4() {
    let q = pressing(0.0);
    let tau_p = Vector4::new(3.0, -2.0, 7.0, 0.5);
    let target = JointTarget {
        q,
        qd: Vector4::zeros(),
        qdd: Vector4::zeros(),
    };
    let cart = CartesianTarget::at_rest(
        Vector3::new(0.45, -0.1, 0.13),
        armdyn::target::orientation::from_yaw(0.0),
    );
    let f = Wrench::zeros();
    let f_d = Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0);
    let zero = Vector4::zeros();
    let input = |t| ControllerInput {
        t,
        q: &q,
        qd: &zero,
        target: &target,
        cartesian: &cart,
        wrench: &f,
        wrench_ref: &f_d,
        wrench_age_s: 0.0,
    };
    let mut h = HybridForcePosition::new(
        Scara,
        Fixed(tau_p),
        ForcePi::new(0.0, 0.0, 0.0),
        TaskFrame::along_z(),
        armdyn::robots::scara::thesis_setup::THESIS_SELECTION,
        HybridSetup::ROWS,
    )
    .unwrap();
    // S = I before the switch: exactly the position loop's torque, no Jacobian inverse.
    assert_eq!(h.step(&input(1.0), 1e-3), tau_p);
    assert_eq!(h.last_solve(), JacobianSolve::NotNeeded);
    // After: joints 1, 2, 4 as before (x, y, yaw position-controlled), d3 from the force loop:
    // with pure feedforward the tool is commanded to exert f_d = -200 N, i.e. push d3 down.
    let tau = h.step(&input(3.0), 1e-3);
    assert_eq!(h.last_solve(), JacobianSolve::Exact);
    for i in [0, 1, 3] {
        assert!(
            abs_diff_eq!(tau[i], tau_p[i], epsilon = EXACT),
            "{tau} vs {tau_p}"
        );
    }
    assert!(abs_diff_eq!(tau[2], 200.0, epsilon = EXACT), "{tau}");
}

#[test]
fn damped_controller_meets_the_force_targets_and_settles_within_1_n() {
    let out = trials::hybrid_trial(ForceController::PiFfVd, ForceReference::Const);
    let mut m = armdyn::robots::scara::thesis_setup::thesis_force_metrics();
    out.samples.iter().for_each(|s| m.push(s));
    let s = m.summary();
    assert!(s.force_overshoot_pct <= 5.0, "{s:?}");
    assert!(s.settling_time_s.is_some_and(|t| t <= 0.1), "{s:?}");
    assert!(s.force_rms_error_last_n <= 2.0, "{s:?}");
    assert!(s.xy_rms_error_contact_mm <= 1.5, "{s:?}");
    // Steady state: within 1 N of the reference over the last second.
    let worst = out
        .samples
        .iter()
        .filter(|x| x.t >= 9.0)
        .map(|x| (x.wrench[2] - x.setpoint.wrench[2]).abs())
        .fold(0.0, f64::max);
    assert!(
        worst < 1.0,
        "force error in the last second up to {worst} N"
    );
    let var = trials::hybrid_trial(ForceController::PiFfVd, ForceReference::Var);
    let mut m = armdyn::robots::scara::thesis_setup::thesis_force_metrics();
    var.samples.iter().for_each(|s| m.push(s));
    assert!(
        m.summary().force_rms_error_last_n <= 5.0,
        "{:?}",
        m.summary()
    );
}

#[test]
fn every_force_law_passes_the_switch_with_a_finite_state() {
    for f in THESIS_FORCE_LAWS {
        for r in ForceReference::ALL {
            let out = trials::hybrid_trial(f, r);
            for s in out.samples.iter().filter(|s| (1.9..=2.5).contains(&s.t)) {
                assert!(
                    s.q.iter()
                        .chain(s.qd.iter())
                        .chain(s.tau.iter())
                        .all(|x| x.is_finite()),
                    "{} {} at {}",
                    f.name(),
                    r.name(),
                    s.t
                );
            }
        }
    }
}

/// The hybrid trial seen through a force sensor (thesis Chapter 6: measurement noise).
fn sensed_trial(sensor: armdyn::contact::ForceSensor) -> armdyn::scenario::RunOutput<4> {
    let (controller, _) = HybridSetup::build(ForceController::PiFfVd).expect("gains");
    let mut sensed = armdyn::control::sensed::Sensed::new(controller, sensor);
    trials::run_trial(
        &mut sensed,
        &armdyn::robots::scara::thesis::ContactTest::thesis(),
        Some(ForceReference::Const.profile()),
        &armdyn::robots::scara::thesis_setup::thesis_surface(),
    )
}

#[test]
fn damped_controller_tolerates_sensor_noise_and_follows_a_biased_sensor() {
    use armdyn::contact::ForceSensor;
    // 5 N of white noise (1 sigma) per axis: still within the ideal sensor's targets.
    let noisy = ForceSensor::new(Wrench::zeros(), Wrench::repeat(5.0), None, 11).unwrap();
    let out = sensed_trial(noisy);
    let mut m = armdyn::robots::scara::thesis_setup::thesis_force_metrics();
    out.samples.iter().for_each(|s| m.push(s));
    let s = m.summary();
    assert!(
        s.force_rms_error_last_n <= 2.0 && s.force_overshoot_pct <= 5.0,
        "{s:?}"
    );
    // A +10 N bias on fz: the loop makes the *measured* force -200 N, so the tool really
    // pushes with -210 N (the sign convention of the measurement).
    let biased = ForceSensor::new(
        Wrench::new(0.0, 0.0, 10.0, 0.0, 0.0, 0.0),
        Wrench::zeros(),
        None,
        0,
    )
    .unwrap();
    let out = sensed_trial(biased);
    let last: Vec<f64> = out
        .samples
        .iter()
        .filter(|s| s.t >= 8.0)
        .map(|s| s.wrench[2])
        .collect();
    let mean = last.iter().sum::<f64>() / last.len() as f64;
    assert!(
        abs_diff_eq!(mean, -210.0, epsilon = 1.0),
        "mean true fz over the last 2 s: {mean} N"
    );
}
