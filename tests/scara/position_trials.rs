//! The position test trajectory (eq. 4.16) under every controller of Chapter 4
//! (issue acceptance: max joint error after 2 s below 1e-3 for the PID family, below 1e-4
//! for computed torque and the corrected full-state feedback designs).

#[allow(dead_code)]
use crate::trials;

use armdyn::metrics::TrackingMetrics;
use armdyn::scenario::PositionController;

fn max_error_after_2s(c: PositionController) -> f64 {
    let out = trials::position_trial(c);
    assert_eq!(out.samples.len(), 10_001);
    assert!(
        out.stats.saturated_samples.iter().all(|&n| n == 0),
        "{:?}",
        out.stats
    );
    let mut m = TrackingMetrics::new(2.0);
    out.samples.iter().for_each(|s| m.push(s));
    m.summary().max_joint_error_after.max()
}

#[test]
fn pid_family_tracks_within_1e_3() {
    for c in [
        PositionController::Pid,
        PositionController::PidFl,
        PositionController::PidFlCentral,
    ] {
        let e = max_error_after_2s(c);
        assert!(e < 1e-3, "{}: max joint error after 2 s = {e:e}", c.name());
    }
}

#[test]
fn model_based_designs_track_within_1e_4() {
    for c in [
        PositionController::ComputedTorque,
        PositionController::FsfPlace,
        PositionController::FsfLqr,
    ] {
        let e = max_error_after_2s(c);
        assert!(e < 1e-4, "{}: max joint error after 2 s = {e:e}", c.name());
    }
}
