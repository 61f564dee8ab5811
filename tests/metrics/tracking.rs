//! `metrics/tracking.rs`: joint tracking errors and torques.

use super::{at, times};
use armdyn::metrics::TrackingMetrics;
use nalgebra::Vector2;

#[test]
fn errors_over_the_run_and_after_the_transient_and_the_largest_torque() {
    let mut m = TrackingMetrics::<2>::new(1.0);
    let mut n = 0;
    for t in times(0.01, 2.0) {
        let mut s = at(t);
        // q_d - q: (0.3, -0.4) rad before 1 s, (0.01, -0.02) from 1 s on.
        s.setpoint.joint.q = Vector2::new(0.5, 0.0);
        s.q = if t < 1.0 - 1e-12 {
            Vector2::new(0.2, 0.4)
        } else {
            Vector2::new(0.49, 0.02)
        };
        s.tau = Vector2::new(-7.0 + t, 2.0 * t);
        m.push(&s);
        n += 1;
    }
    assert_eq!(n, 200);
    let r = m.summary();
    assert!((r.rms_joint_error_after - Vector2::new(0.01, 0.02)).norm() < 1e-15);
    assert!((r.max_joint_error_after - Vector2::new(0.01, 0.02)).norm() < 1e-15);
    // Half the samples each: rms = sqrt((e1^2 + e2^2) / 2).
    let whole = Vector2::new(
        ((0.09 + 0.0001) / 2.0_f64).sqrt(),
        ((0.16 + 0.0004) / 2.0_f64).sqrt(),
    );
    assert!(
        (r.rms_joint_error - whole).norm() < 1e-14,
        "{}",
        r.rms_joint_error
    );
    assert!(
        (r.max_abs_tau - Vector2::new(7.0, 3.98)).norm() < 1e-12,
        "{}",
        r.max_abs_tau
    );
    assert_eq!(r.after_s, 1.0);
}

#[test]
fn an_empty_window_gives_zeros() {
    let mut m = TrackingMetrics::<2>::new(5.0);
    let mut s = at(1.0);
    s.q = Vector2::new(0.1, 0.2);
    m.push(&s);
    let r = m.summary();
    assert_eq!(r.rms_joint_error_after, Vector2::zeros());
    assert_eq!(r.max_joint_error_after, Vector2::zeros());
    assert!((r.rms_joint_error - Vector2::new(0.1, 0.2)).norm() < 1e-15);
}
