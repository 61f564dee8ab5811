//! Tests of `armdyn::control::task_space`: the task-space law: the closed-loop task
//! acceleration is the commanded one, and the posture moves the joints only in the task's null
//! space (a check the hybrid law's and the impedance's tests share).

use armdyn::control::task_space::*;
use armdyn::control::{Controller, ControllerInput};
use armdyn::model::{forward_dynamics, JointVector, Panda, RobotModel, Ur5};
use armdyn::target::{orientation, CartesianTarget, JointTarget};
use nalgebra::{UnitQuaternion, Vector3, Vector6};

fn input<'a, const N: usize>(
    q: &'a JointVector<N>,
    qd: &'a JointVector<N>,
    target: &'a JointTarget<N>,
    cartesian: &'a CartesianTarget,
    w: &'a Vector6<f64>,
) -> ControllerInput<'a, N> {
    ControllerInput {
        t: 0.0,
        q,
        qd,
        target,
        cartesian,
        wrench: w,
        wrench_ref: w,
        wrench_age_s: 0.0,
    }
}

#[test]
fn the_closed_loop_task_acceleration_is_the_commanded_one() {
    // UR5 (square task): the tool's acceleration under the law equals a_d + Kd e' + Kp e.
    let robot = Ur5;
    let q = JointVector::<6>::from([0.3, -1.2, 1.4, -1.8, -1.5, 0.2]);
    let qd = JointVector::<6>::from([0.1, -0.2, 0.3, 0.1, -0.1, 0.2]);
    let pose = robot.end_effector_pose(&q);
    let mut c = CartesianTarget::at_rest(
        pose.fixed_view::<3, 1>(0, 3).into_owned() + Vector3::new(0.01, -0.02, 0.005),
        nalgebra::UnitQuaternion::from_scaled_axis(Vector3::new(0.02, -0.01, 0.03))
            * orientation::of_pose(&pose),
    );
    c.acceleration = Vector3::new(0.3, -0.1, 0.2);
    let g = TaskSpaceGains::critically_damped::<6, Ur5>(&[20.0; 6], 1.0, 10.0, false);
    let mut law = TaskSpaceInverseDynamics::new(robot, g);
    let (z, w) = (JointTarget::at_rest(q), Vector6::zeros());
    let tau = law.step(&input(&q, &qd, &z, &c, &w), 1e-3);
    let qdd = forward_dynamics(&robot, &q, &qd, &tau, &JointVector::zeros()).unwrap();
    let acc = robot.jacobian(&q) * qdd + robot.jdot_qd(&q, &qd);
    let e = Ur5::TASK.pose_error(
        &c.position,
        &c.orientation,
        &pose.fixed_view::<3, 1>(0, 3).into_owned(),
        &orientation::of_pose(&pose),
    );
    let ed = c.twist() - robot.jacobian(&q) * qd;
    let expected = c.acceleration_twist() + g.kd.component_mul(&ed) + g.kp.component_mul(&e);
    assert!(
        (acc - expected).norm() < 1e-8 * expected.norm(),
        "{acc} vs {expected}"
    );
}

#[test]
fn the_posture_term_does_not_move_the_tool() {
    let g = TaskSpaceGains::critically_damped::<7, Panda>(&[20.0; 6], 1.0, 10.0, true);
    posture_acts_in_the_null_space_only(|_| TaskSpaceInverseDynamics::new(Panda, g));
}

/// A check shared by the task-space laws' tests: the law `make` builds for the Panda's reference orientation (given to it), stepped
/// at rest on its reference pose with the posture target off its joints: the posture moves
/// the joints (with the gains of the tests, over 1e-3 rad/s^2), and only in the task's null
/// space (the tool's acceleration under 1e-9).
pub(crate) fn posture_acts_in_the_null_space_only<C: Controller<7>>(
    make: impl FnOnce(UnitQuaternion<f64>) -> C,
) {
    let robot = Panda;
    let q = JointVector::<7>::from([0.1, -0.6, 0.2, -2.0, 0.1, 1.6, 0.7]);
    let qd = JointVector::<7>::zeros();
    let pose = robot.end_effector_pose(&q);
    let r = orientation::of_pose(&pose);
    let c = CartesianTarget::at_rest(pose.fixed_view::<3, 1>(0, 3).into_owned(), r);
    let posture =
        JointTarget::at_rest(q + JointVector::<7>::from([0.2, 0.0, -0.3, 0.1, 0.0, 0.0, 0.1]));
    let w = Vector6::zeros();
    let input = ControllerInput {
        t: 0.0,
        q: &q,
        qd: &qd,
        target: &posture,
        cartesian: &c,
        wrench: &w,
        wrench_ref: &w,
        wrench_age_s: 0.0,
    };
    let tau = make(r).step(&input, 1e-3);
    let qdd = forward_dynamics(&robot, &q, &qd, &tau, &JointVector::zeros()).unwrap();
    assert!(qdd.norm() > 1e-3, "the posture moves the joints");
    let acc = robot.jacobian(&q) * qdd;
    assert!(acc.norm() < 1e-9, "{acc}");
}
