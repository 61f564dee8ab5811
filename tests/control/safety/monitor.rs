//! Tests of `armdyn::control::safety::monitor`: the safety monitor: its peaks, and a crossing
//! naming its joint and value.

use armdyn::control::safety::monitor::*;
use armdyn::control::safety::{SafetyLimits, TripCause};
use nalgebra::{SVector, Vector2, Vector3, Vector6};

fn observe(m: &mut SafetyMonitor<f64, 2>, t: f64, q: Vector2<f64>, qd: Vector2<f64>) {
    let (p, v) = (Vector3::new(0.3, 0.0, 0.1), Vector3::zeros());
    let x = Observation {
        t,
        q: &q,
        qd: &qd,
        position: &p,
        velocity: &v,
        force_ref_n: 0.0,
        force_controlled: false,
    };
    m.state(&x, &Vector6::zeros(), 1e-3);
}

#[test]
fn the_bounds_pass_keeps_the_peaks_and_a_crossing_names_its_joint_and_value() {
    let mut l = SafetyLimits::<f64, 2>::defaults(
        SVector::repeat(-1.0),
        SVector::repeat(1.0),
        SVector::repeat(10.0),
        None,
        0.0,
    );
    l.joint_margin = Some(Vector2::new(0.1, 0.1));
    l.max_joint_speed = Some(Vector2::new(2.0, 2.0));
    let mut m = SafetyMonitor::new(l);
    observe(
        &mut m,
        0.0,
        Vector2::new(0.5, -0.2),
        Vector2::new(1.5, -0.5),
    );
    observe(
        &mut m,
        0.001,
        Vector2::new(0.0, -0.7),
        Vector2::new(0.1, -1.9),
    );
    assert!(!m.tripped());
    let p = m.peaks();
    assert_eq!(
        p.joint_limit_distance,
        Vector2::new(0.5, 0.30000000000000004)
    );
    assert_eq!(p.joint_speed, Vector2::new(1.5, 1.9));
    // Joint 1 inside its margin (0.05 from its upper limit): named, with its distance.
    observe(&mut m, 0.002, Vector2::new(0.0, 0.95), Vector2::zeros());
    let trip = *m.trips().first().unwrap();
    assert_eq!(trip.cause, TripCause::JointLimit(1));
    approx::assert_relative_eq!(trip.value, 0.05, max_relative = 1e-12);
    assert_eq!(trip.t, 0.002);
    // A NaN joint speed fails the bounds and trips joint 0's speed check.
    let mut m = SafetyMonitor::new(l);
    observe(&mut m, 0.0, Vector2::zeros(), Vector2::new(f64::NAN, 0.0));
    assert_eq!(m.trips().first().unwrap().cause, TripCause::JointSpeed(0));
}
