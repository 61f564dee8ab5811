//! Tests of `armdyn::trajectory::waypoints`: the waypoint reference: derivatives against
//! differences, holds outside its times, refuses bad points.

use armdyn::target::{orientation, PoseSample};
use armdyn::trajectory::waypoints::*;
use armdyn::trajectory::CartesianTrajectory;
use nalgebra::Vector3;

fn two(kind: Interpolation) -> Waypoints {
    Waypoints::new(
        &[
            PoseSample::with_yaw(1.0, Vector3::new(0.5, -0.3, 0.13), 0.0),
            PoseSample::new(
                9.0,
                Vector3::new(0.5, 0.3, 0.13),
                orientation::from_rpy(0.3, -0.2, 0.4),
            ),
        ],
        kind,
    )
    .unwrap()
}

#[test]
fn derivatives_match_differences() {
    for kind in [Interpolation::Linear, Interpolation::Quintic] {
        let w = two(kind);
        let h = 1e-6;
        for t in [1.5, 3.0, 5.0, 8.7] {
            let (a, b, m) = (w.at(t - h), w.at(t + h), w.at(t));
            let v = (b.position - a.position) / (2.0 * h);
            let acc = (b.velocity - a.velocity) / (2.0 * h);
            assert!((v - m.velocity).norm() < 1e-8, "{kind:?} {t}");
            assert!((acc - m.acceleration).norm() < 1e-6, "{kind:?} {t}");
            // The angular velocity and acceleration are the derivatives of the orientation
            // and of the angular velocity.
            let w = orientation::error(&b.orientation, &a.orientation) / (2.0 * h);
            assert!((w - m.angular_velocity).norm() < 1e-8, "{kind:?} {t}");
            let alpha = (b.angular_velocity - a.angular_velocity) / (2.0 * h);
            assert!(
                (alpha - m.angular_acceleration).norm() < 1e-6,
                "{kind:?} {t}"
            );
        }
    }
}

#[test]
fn holds_outside_and_refuses_bad_points() {
    let w = two(Interpolation::Linear);
    assert_eq!(w.at(0.0).position, Vector3::new(0.5, -0.3, 0.13));
    assert!(
        (w.at(20.0)
            .orientation
            .angle_to(&orientation::from_rpy(0.3, -0.2, 0.4)))
            < 1e-15
    );
    assert_eq!(w.duration(), 9.0);
    let p = PoseSample::with_yaw(1.0, Vector3::zeros(), 0.0);
    assert_eq!(
        Waypoints::new(&[p], Interpolation::Linear),
        Err(WaypointError::TooFew(1))
    );
    assert!(matches!(
        Waypoints::new(&[p, p], Interpolation::Linear),
        Err(WaypointError::NotIncreasing { index: 1, .. })
    ));
}
