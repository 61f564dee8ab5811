//! Tests of `armdyn::control::impedance`: the Cartesian impedance: the virtual point gives the
//! force in series, the wrench is the stiffness times the error in the task frame, and the
//! posture acts in the null space only.

use armdyn::control::impedance::*;
use armdyn::control::selection::SelectionPolicy;
use armdyn::control::task_frame::TaskFrame;
use armdyn::control::tool_orientation::ToolOrientation;
use armdyn::control::{Controller, ControllerInput};
use armdyn::model::{JointVector, Panda, RobotModel, Ur5};
use armdyn::target::{orientation, CartesianTarget, JointTarget};
use nalgebra::{UnitQuaternion, Vector3, Vector6};

#[test]
fn the_virtual_point_gives_the_force_in_series() {
    let g = ImpedanceGains {
        normal_stiffness: 2000.0,
        normal_damping: 0.0,
        tangential_stiffness: 0.0,
        tangential_damping: 0.0,
        yaw_stiffness: 0.0,
        yaw_damping: 0.0,
        tilt_stiffness: 0.0,
        tilt_damping: 0.0,
        contact_stiffness: 1e4,
    };
    // At rest: K_n (x_d - x) = k x (x < 0 inside) and f = k x.
    let x_d = g.virtual_gap(-200.0);
    let x = g.normal_stiffness * x_d / (g.normal_stiffness + 1e4);
    assert!((1e4 * x + 200.0).abs() < 1e-9);
    // 5 mm higher surface: 5 mm more penetration through the series spring.
    assert!((g.series_stiffness(1e4) * 0.005 - 8.333_333_333).abs() < 1e-6);
}

fn gains() -> ImpedanceGains {
    ImpedanceGains {
        normal_stiffness: 2000.0,
        normal_damping: 80.0,
        tangential_stiffness: 20_000.0,
        tangential_damping: 300.0,
        yaw_stiffness: 50.0,
        yaw_damping: 2.0,
        tilt_stiffness: 100.0,
        tilt_damping: 4.0,
        contact_stiffness: 1e4,
    }
}

#[test]
fn the_wrench_is_the_stiffness_times_the_error_in_the_task_frame() {
    // UR5 at rest, the reference 1 cm off along x and 0.01 rad about the normal: J^T F
    // with F = [k_t e_p; k_yaw e_o] plus gravity; the tool's x axis held down.
    let robot = Ur5;
    let h = core::f64::consts::FRAC_PI_2;
    let q = JointVector::<6>::from([0.0, -h, h, -h, -h, 0.0]);
    let pose = robot.end_effector_pose(&q);
    let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
    let r = orientation::of_pose(&pose);
    let axis = r.inverse() * -Vector3::z();
    let c = CartesianTarget::at_rest(
        p + Vector3::new(0.01, 0.0, 0.0),
        UnitQuaternion::from_scaled_axis(Vector3::new(0.0, 0.0, 0.01)) * r,
    );
    let mut law = CartesianImpedance::new(
        robot,
        gains(),
        PostureGains { kp: 0.0, kd: 0.0 },
        TaskFrame::Fixed(Vector3::z()),
        ToolOrientation::AlongNormal(axis),
        SelectionPolicy::Time { switch_s: 1.0 },
    )
    .unwrap();
    let qd = JointVector::<6>::zeros();
    let (z, w) = (JointTarget::at_rest(q), Vector6::zeros());
    let input = ControllerInput {
        t: 0.0,
        q: &q,
        qd: &qd,
        target: &z,
        cartesian: &c,
        wrench: &w,
        wrench_ref: &w,
        wrench_age_s: 0.0,
    };
    let tau = law.step(&input, 1e-3);
    let f = Vector6::new(200.0, 0.0, 0.0, 0.0, 0.0, 0.5);
    let expected = robot.jacobian(&q).transpose() * f + robot.gravity(&q);
    assert!((tau - expected).norm() < 1e-6, "{tau} vs {expected}");
    assert!(!law.report().force_controlled);
}

#[test]
fn the_posture_acts_in_the_null_space_only() {
    let posture = PostureGains {
        kp: 100.0,
        kd: 20.0,
    };
    crate::task_space::posture_acts_in_the_null_space_only(|_| {
        let frame = TaskFrame::Fixed(Vector3::z());
        let time = SelectionPolicy::Time { switch_s: 1.0 };
        let reference = ToolOrientation::Reference;
        CartesianImpedance::new(Panda, gains(), posture, frame, reference, time).unwrap()
    });
}
