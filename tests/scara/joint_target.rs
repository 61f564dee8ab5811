//! Tests of `armdyn::robots::scara::joint_target`: the SCARA's joint targets: exact for regular
//! targets, finite and flagged for a stretched arm.

use armdyn::model::{RobotModel, Scara};
use armdyn::robots::scara::geometry::{Elbow, ScaraGeometry};
use armdyn::robots::scara::singularity::{reduced_jacobian, Conditioning, MAX_DAMPING};
use armdyn::target::CartesianTarget;
use nalgebra::Vector3;

fn ik() -> ScaraGeometry {
    ScaraGeometry::from_model(&Scara)
}

#[test]
fn stretched_arm_is_finite_and_flagged() {
    let mut target = CartesianTarget::at_rest(
        Vector3::new(0.8, 0.0, 0.2),
        armdyn::target::orientation::from_yaw(0.0),
    );
    target.velocity = Vector3::new(-0.1, 0.05, 0.01);
    target.angular_velocity.z = 0.2;
    target.acceleration = Vector3::new(0.3, -0.2, 0.1);
    for elbow in [Elbow::Up, Elbow::Down] {
        let r = ik().joint_target(&target, elbow).unwrap();
        assert_eq!(r.target.q[1], 0.0);
        assert_eq!(
            r.conditioning,
            Conditioning::Damped {
                sin_q2: 0.0,
                lambda: MAX_DAMPING
            }
        );
        assert!(r
            .target
            .qd
            .iter()
            .chain(r.target.qdd.iter())
            .all(|v| v.is_finite()));
        // z and yaw rows are met exactly; the tangential velocity (y here) too, since only
        // the radial direction is lost.
        let v = reduced_jacobian(&r.target.q) * r.target.qd;
        assert!((v[2] - 0.01).abs() < 1e-15 && (v[3] - 0.2).abs() < 1e-15);
        assert!((v[1] - 0.05).abs() < 1e-12, "{v}");
        assert!(v[0].abs() < 1e-12); // the radial component is dropped
    }
}

#[test]
fn regular_targets_are_exact() {
    let mut target = CartesianTarget::at_rest(
        Vector3::new(0.45, -0.3, 0.12),
        armdyn::target::orientation::from_yaw(0.7),
    );
    target.velocity = Vector3::new(0.2, 0.1, -0.05);
    target.angular_velocity.z = -0.4;
    let r = ik().joint_target(&target, Elbow::Down).unwrap();
    assert_eq!(r.conditioning, Conditioning::Regular);
    let v = Scara.jacobian(&r.target.q) * r.target.qd;
    assert!((v.fixed_rows::<3>(0) - target.velocity).norm() < 1e-14);
    assert!((v[5] - target.angular_velocity.z).abs() < 1e-14);
}
