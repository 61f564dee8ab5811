//! `metrics/alignment.rs`: the tool axis against the inward normal, and a redundant arm's
//! posture.

use super::{at, times};
use armdyn::contact::{ContactSurface, Scene};
use armdyn::metrics::{AlignmentMetrics, PostureMetrics};
use armdyn::surface::SurfaceGeometry;
use nalgebra::{UnitQuaternion, Vector2, Vector3};

#[test]
fn the_angle_of_the_tool_axis_from_the_inward_normal_while_pressing() {
    let scene = Scene::new(&[ContactSurface {
        geometry: SurfaceGeometry::plane(Vector3::zeros(), Vector3::z(), [1.0, 1.0]),
        stiffness: 10_000.0,
        damping: 0.0,
        friction: 0.0,
    }])
    .unwrap();
    let mut m = AlignmentMetrics::new(Vector3::z());
    for t in times(0.01, 1.0) {
        let mut s = at(t);
        // The tool's z axis turned down, then tilted 10 degrees; 30 degrees in the second half.
        let tilt: f64 = if t < 0.5 - 1e-12 { 10.0 } else { 30.0 };
        s.orientation = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), tilt.to_radians())
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI);
        // Pressing from 0.2 s, force controlled from 0.4 s.
        s.force_controlled = t >= 0.4 - 1e-12;
        if t >= 0.2 - 1e-12 {
            s.wrench[2] = -10.0;
        }
        m.push(&s, &scene);
    }
    let r = m.summary();
    assert_eq!(r.samples, 60);
    assert!((r.max_deg - 30.0).abs() < 1e-9, "{r:?}");
    // 10 samples at 10 degrees, 50 at 30.
    let rms = ((10.0 * 100.0 + 50.0 * 900.0) / 60.0_f64).sqrt();
    assert!((r.rms_deg - rms).abs() < 1e-9, "{r:?}");
}

#[test]
fn the_posture_error_is_the_norm_over_the_joints_from_after_s() {
    let mut m = PostureMetrics::new(0.5);
    for t in times(0.01, 1.0) {
        let mut s = at(t);
        s.setpoint.joint.q = Vector2::new(1.0, 1.0);
        s.q = if t < 0.5 - 1e-12 {
            Vector2::new(-2.0, 3.0)
        } else {
            Vector2::new(0.7, 1.4)
        };
        m.push(&s);
    }
    let r = m.summary();
    assert!(
        (r.rms_rad - 0.5).abs() < 1e-15 && (r.max_rad - 0.5).abs() < 1e-15,
        "{r:?}"
    );
    let empty = PostureMetrics::new(0.0).summary();
    assert_eq!((empty.rms_rad, empty.max_rad), (0.0, 0.0));
}
