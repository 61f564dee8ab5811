//! Kinematics of every generated robot against the robot description:
//! the generated frame poses equal an independent forward kinematics built here from
//! `robots/*.toml` (a DH product, or the URDF's link tree read with `urdf-rs`), the metadata equals the description, and the geometric Jacobian equals
//! central differences of the forward kinematics.

use crate::common;

use approx::abs_diff_eq;
use armdyn::model::{JointKind, RobotModel};
use common::{assert_close, load_robot, max_abs, vee, SEED, STATES};
use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

/// Generated frame poses vs. the independent DH product (same math, different code path).
const TOL_FK: f64 = 1e-12;
/// Jacobian vs. central differences of the forward kinematics (step `H_JACOBIAN`).
const TOL_JACOBIAN: f64 = 1e-8;
const H_JACOBIAN: f64 = 1e-6;

fn frame_poses_match_description<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED, STATES) {
        let q = state.q;
        let expected = desc.frame_poses(q.as_slice());
        let got = robot.frame_poses(&q);
        for (i, (g, e)) in got.iter().zip(&expected).enumerate() {
            assert_close(
                &format!("pose of frame {}", i + 1),
                g,
                e,
                TOL_FK,
                max_abs(e),
                &state,
            );
        }
        let ee = robot.end_effector_pose(&q);
        assert_close(
            "end-effector pose",
            &ee,
            &desc.end_effector(q.as_slice()),
            TOL_FK,
            max_abs(&ee),
            &state,
        );
    }
}

fn metadata_matches_description<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    assert_eq!(robot.name(), name);
    assert_eq!(R::DOF, desc.dof());
    assert_eq!(R::GRAVITY, [desc.gravity.x, desc.gravity.y, desc.gravity.z]);
    for (i, joint) in desc.joints.iter().enumerate() {
        assert_eq!(R::JOINT_NAMES[i], joint.name, "joint {i} name");
        let kind = if joint.prismatic {
            JointKind::Prismatic
        } else {
            JointKind::Revolute
        };
        assert_eq!(R::JOINT_KINDS[i], kind, "joint {i} kind");
        for b in 0..2 {
            let (got, want) = (R::JOINT_LIMITS[i][b], joint.limits[b]);
            assert!(
                abs_diff_eq!(got, want, epsilon = 1e-15 * want.abs().max(1.0)),
                "joint {i} limit {b}: {got} vs {want}"
            );
        }
        assert_eq!(R::EFFORT_LIMITS[i], joint.effort, "joint {i} effort");
    }
    assert_eq!(R::SOURCE_SHA256.len(), 64, "SOURCE_SHA256 is 64 hex digits");
    assert!(!R::OPERATION_COUNTS.is_empty());
}

fn rotation(pose: &nalgebra::Matrix4<f64>) -> Matrix3<f64> {
    pose.fixed_view::<3, 3>(0, 0).into_owned()
}

fn translation(pose: &nalgebra::Matrix4<f64>) -> Vector3<f64> {
    pose.fixed_view::<3, 1>(0, 3).into_owned()
}

fn jacobian_matches_fk_differences<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED ^ 0x1, STATES) {
        let (q, qd) = (state.q, state.qd);
        let r0 = rotation(&desc.end_effector(q.as_slice()));
        let mut numeric = SMatrix::<f64, 6, N>::zeros();
        for j in 0..N {
            let mut plus = q;
            let mut minus = q;
            plus[j] += H_JACOBIAN;
            minus[j] -= H_JACOBIAN;
            let tp = desc.end_effector(plus.as_slice());
            let tm = desc.end_effector(minus.as_slice());
            let v = (translation(&tp) - translation(&tm)) / (2.0 * H_JACOBIAN);
            let rdot = (rotation(&tp) - rotation(&tm)) / (2.0 * H_JACOBIAN);
            let w = vee(&(rdot * r0.transpose()));
            numeric.fixed_view_mut::<3, 1>(0, j).copy_from(&v);
            numeric.fixed_view_mut::<3, 1>(3, j).copy_from(&w);
        }
        let got = robot.jacobian(&q);
        assert_close(
            "jacobian",
            &got,
            &numeric,
            TOL_JACOBIAN,
            max_abs(&numeric),
            &state,
        );
        // And the twist it predicts for this qd (a different contraction of the same data).
        let twist: SVector<f64, 6> = got * qd;
        let expected: SVector<f64, 6> = numeric * qd;
        assert_close(
            "J qd",
            &twist,
            &expected,
            TOL_JACOBIAN,
            max_abs(&expected) + max_abs(&numeric),
            &state,
        );
    }
}

per_robot!(
    frame_poses_match_description,
    metadata_matches_description,
    jacobian_matches_fk_differences,
);
