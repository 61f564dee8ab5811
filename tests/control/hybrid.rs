//! Tests of `armdyn::control::hybrid`: the hybrid law in the full task frame: the force row
//! commands the force and the other rows their motion, a redundant arm before the switch, and
//! the damping against the force reference's own motion.

use armdyn::control::force::ForcePi;
use armdyn::control::hybrid::*;
use armdyn::control::selection::SelectionPolicy;
use armdyn::control::task_frame::TaskFrame;
use armdyn::control::task_space::TaskSpaceGains;
use armdyn::control::tool_orientation::ToolOrientation;
use armdyn::control::{Controller, ControllerInput};
use armdyn::model::{JointVector, Panda, RobotModel, Ur5};
use armdyn::target::{orientation, CartesianTarget, JointTarget};
use nalgebra::{UnitQuaternion, Vector3, Vector6};

fn input<'a, const N: usize>(
    t: f64,
    q: &'a JointVector<N>,
    qd: &'a JointVector<N>,
    target: &'a JointTarget<N>,
    cartesian: &'a CartesianTarget,
    w: &'a Vector6<f64>,
    w_ref: &'a Vector6<f64>,
) -> ControllerInput<'a, N> {
    ControllerInput {
        t,
        q,
        qd,
        target,
        cartesian,
        wrench: w,
        wrench_ref: w_ref,
        wrench_age_s: 0.0,
    }
}

fn law<const N: usize, R: RobotModel<N>>(robot: R, tool: Vector3<f64>) -> TaskSpaceHybrid<N, R> {
    let g = TaskSpaceGains::critically_damped::<N, R>(&[30.0; 6], 1.0, 10.0, true);
    TaskSpaceHybrid::in_task_frame(
        robot,
        g,
        ForcePi::new(2.0, 20.0, 50.0),
        TaskFrame::Fixed(Vector3::z()),
        ToolOrientation::AlongNormal(tool),
        SelectionPolicy::Time { switch_s: 1.0 },
    )
    .unwrap()
}

/// A UR5 configuration, its tool position and orientation, and the tool-frame axis that
/// points along -z there (held along the inward normal of a table).
fn ur5_pose() -> (
    JointVector<6>,
    Vector3<f64>,
    UnitQuaternion<f64>,
    Vector3<f64>,
) {
    let q = JointVector::<6>::from([0.0, -1.2, 1.6, -1.97, -core::f64::consts::FRAC_PI_2, 0.0]);
    let pose = Ur5.end_effector_pose(&q);
    let r = orientation::of_pose(&pose);
    (
        q,
        pose.fixed_view::<3, 1>(0, 3).into_owned(),
        r,
        r.inverse() * -Vector3::z(),
    )
}

#[test]
fn the_force_row_commands_the_force_and_the_other_rows_their_motion() {
    // UR5 at rest on its reference, after the switch: the tool exerts the force law's
    // command along n (no motion error, so no other wrench), and at rest the commanded
    // torque is J^T F + g.
    let robot = Ur5;
    let (q, p, r, axis) = ur5_pose();
    let mut law = law(robot, axis);
    let c = CartesianTarget::at_rest(p, r);
    let qd = JointVector::<6>::zeros();
    let z = JointTarget::at_rest(q);
    let w = Vector6::new(0.0, 0.0, -30.0, 0.0, 0.0, 0.0);
    let tau = law.step(&input(2.0, &q, &qd, &z, &c, &w, &w), 1e-3);
    // Measured = desired: f_f = f_d = -30 N (plus the integral of one period's zero error).
    let expected = robot.jacobian(&q).transpose() * w + robot.gravity(&q);
    assert!(
        (tau - expected).norm() < 1e-9 * expected.norm(),
        "{tau} vs {expected}"
    );
}

#[test]
fn before_the_switch_a_redundant_arm_moves_only_as_the_motion_law_asks() {
    // The tool aligned to the normal: the task acceleration is zero, whatever the
    // posture term does.
    crate::task_space::posture_acts_in_the_null_space_only(|r| {
        law(Panda, r.inverse() * -Vector3::z())
    });
}

#[test]
fn the_damping_acts_against_the_force_references_own_motion() {
    // UR5 on its reference after the switch, the force reference ramping by 1 N per
    // period on a 10 kN/m contact: the reference asks for v_n = (df_d/dt) / k = -0.1 m/s,
    // and the tool moves at exactly that. With the reference's motion the damping sees no
    // error; without it, it brakes with Kvd * 0.1 m/s = 5 N along n.
    let robot = Ur5;
    let (q, p, r, axis) = ur5_pose();
    let j = robot.jacobian(&q);
    // Joint velocities moving the tool at -0.1 m/s along z, nothing else.
    let twist = nalgebra::Vector6::new(0.0, 0.0, -0.1, 0.0, 0.0, 0.0);
    let qd = j.lu().solve(&twist).unwrap();
    let z = JointTarget::at_rest(q);
    let mut c = CartesianTarget::at_rest(p, r);
    c.velocity = Vector3::new(0.0, 0.0, -0.1);
    let torques = |reference_motion: Option<f64>| {
        let mut law = law(robot, axis).with_reference_motion(reference_motion);
        let mut tau = JointVector::<6>::zeros();
        for (k, f) in [-20.0, -21.0].iter().enumerate() {
            let w = Vector6::new(0.0, 0.0, *f, 0.0, 0.0, 0.0);
            tau = law.step(&input(2.0 + 1e-3 * k as f64, &q, &qd, &z, &c, &w, &w), 1e-3);
        }
        tau
    };
    let (with, without) = (torques(Some(1e4)), torques(None));
    // The difference is J^T n (Kvd v_ref) = J^T (0, 0, 50 * -0.1): 5 N pushing down more.
    let expected = j.transpose() * Vector6::new(0.0, 0.0, -5.0, 0.0, 0.0, 0.0);
    assert!(
        ((with - without) - expected).norm() < 1e-9 * expected.norm(),
        "{}",
        with - without
    );
}
