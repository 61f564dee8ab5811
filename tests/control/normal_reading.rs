//! Tests of `armdyn::control::normal_reading`: the normal reading: forces and heights along the
//! normal, and contact switching starting its ramp from the measured force.

use armdyn::control::normal_reading::*;
use armdyn::control::selection::{ContactSwitch, Decision, SelectionPolicy};
use armdyn::control::task_frame::TaskFrame;
use armdyn::control::ControllerInput;
use armdyn::model::JointVector;
use armdyn::surface::SurfaceGeometry;
use armdyn::target::{CartesianTarget, JointTarget};
use nalgebra::{UnitQuaternion, Vector3, Vector6};

fn reading(selection: SelectionPolicy, t: f64, f_z: f64, tool_z: f64) -> NormalReading {
    let frame = TaskFrame::Surface(SurfaceGeometry::plane(
        Vector3::zeros(),
        Vector3::z(),
        [1.0, 1.0],
    ));
    let mut s = NormalSelector::new(frame, selection);
    let q = JointVector::<1>::zeros();
    let target = JointTarget::at_rest(q);
    let c = CartesianTarget::at_rest(Vector3::new(0.0, 0.0, -0.01), UnitQuaternion::identity());
    let w = Vector6::new(0.0, 0.0, f_z, 0.0, 0.0, 0.0);
    let w_ref = Vector6::new(0.0, 0.0, -50.0, 0.0, 0.0, 0.0);
    let input = ControllerInput {
        t,
        q: &q,
        qd: &q,
        target: &target,
        cartesian: &c,
        wrench: &w,
        wrench_ref: &w_ref,
        wrench_age_s: 0.0,
    };
    let r = s.read(&input, &Vector3::new(0.0, 0.0, tool_z), 1e-3);
    assert_eq!(s.force_active(), r.forcing());
    r
}

#[test]
fn the_reading_names_the_forces_and_heights_along_the_normal() {
    let r = reading(SelectionPolicy::Time { switch_s: 1.0 }, 2.0, -20.0, 0.003);
    assert_eq!((r.n, r.f_n, r.reference_n), (Vector3::z(), -20.0, -50.0));
    assert!((r.tool_gap.unwrap() - 0.003).abs() < 1e-15);
    assert!((r.reference_gap.unwrap() + 0.01).abs() < 1e-15);
    assert_eq!(r.f_d, -50.0);
    let before = reading(SelectionPolicy::Time { switch_s: 1.0 }, 0.5, -20.0, 0.003);
    assert!(!before.forcing());
}

#[test]
fn contact_switching_starts_the_ramp_from_the_measured_force() {
    let mut c = ContactSwitch::for_sensor(0.0, 0.0);
    c.debounce_s = 1e-3; // one period
    let r = reading(SelectionPolicy::Contact(c), 0.0, -20.0, -0.001);
    assert!(r.forcing());
    // At the switch the force reference is the measured force; it ramps to -50 N.
    assert_eq!(r.f_d, -20.0);
    // Without a push, position control (approaching: the reference is below the surface).
    let r = reading(SelectionPolicy::Contact(c), 0.0, 0.0, 0.002);
    assert!(matches!(r.decision, Decision::Position { .. }));
}
