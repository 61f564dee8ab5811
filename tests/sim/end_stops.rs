//! Tests of `armdyn::sim::end_stops`: the end stops push back past the limits only, never pull.

use armdyn::model::Scara;
use armdyn::sim::end_stops::*;
use nalgebra::Vector4;

#[test]
fn stops_push_back_past_the_limits_only_and_never_pull() {
    let s = EndStops::from_model(&Scara);
    let k3 = s.stiffness()[2];
    assert!(
        (k3 / (4.94 * END_STOP_OMEGA * END_STOP_OMEGA) - 1.0).abs() < 1e-3,
        "{k3}"
    );
    let inside = Vector4::new(0.0, 0.0, 0.2, 0.0);
    assert_eq!(s.torque(&inside, &Vector4::repeat(5.0)), Vector4::zeros());
    let past = Vector4::new(0.0, 0.0, 0.352, 0.0);
    let t = s.torque(&past, &Vector4::zeros());
    assert!((t[2] + k3 * 0.002).abs() < 1e-6 * k3, "{t}");
    assert!(s.engaged(&past, 2) && !s.engaged(&past, 0));
    // Leaving the stop fast: the damping would pull it back in, so nothing acts.
    assert_eq!(s.torque(&past, &Vector4::new(0.0, 0.0, -10.0, 0.0))[2], 0.0);
    let below = Vector4::new(0.0, 0.0, 0.0, 0.0);
    assert!(s.torque(&below, &Vector4::zeros())[2] > 0.0);
}
