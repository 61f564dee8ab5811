//! `metrics/force.rs`: the thesis's force metrics along base z.

use super::{at, times};
use armdyn::metrics::ForceMetrics;
use nalgebra::Vector3;

/// A run of 3 s, force control from 1 s with a reference of 10 N down: the force overshoots
/// to 12 N until 1.5 s and holds 10.2 N from then on; the tool is 3 mm, 4 mm off in x-y and
/// its lowest point is 2 mm below zero.
fn step_response() -> ForceMetrics {
    let mut m = ForceMetrics::new(1.0, 3.0, 1.0, 10.0, 0.05);
    for t in times(0.01, 3.0) {
        let mut s = at(t);
        s.position = Vector3::new(0.0, 0.0, -0.002 * (t / 3.0));
        s.setpoint.cartesian.position = Vector3::new(0.003, 0.004, 0.0);
        if t >= 1.0 - 1e-12 {
            s.setpoint.wrench[2] = -10.0;
            s.wrench[2] = if t < 1.5 - 1e-12 { -12.0 } else { -10.2 };
        }
        m.push(&s);
    }
    m
}

#[test]
fn overshoot_settling_and_the_last_window_of_a_step_response() {
    let r = step_response().summary();
    // 2 N beyond 10 N.
    assert!((r.force_overshoot_pct - 20.0).abs() < 1e-12, "{r:?}");
    // Last outside the 0.5 N band at 1.49 s.
    assert!((r.settling_time_s.unwrap() - 0.49).abs() < 1e-12, "{r:?}");
    assert!((r.force_rms_error_last_n - 0.2).abs() < 1e-12, "{r:?}");
    assert!((r.xy_rms_error_contact_mm - 5.0).abs() < 1e-12, "{r:?}");
    assert!((r.min_z_m + 0.002 * 2.99 / 3.0).abs() < 1e-15, "{r:?}");
}

#[test]
fn a_force_outside_the_band_at_the_end_has_not_settled_and_a_shortfall_is_no_overshoot() {
    let mut m = ForceMetrics::new(0.5, 1.0, 0.5, 10.0, 0.05);
    for t in times(0.01, 1.01) {
        let mut s = at(t);
        s.setpoint.wrench[2] = -10.0;
        // Pushing 8 N: short of the reference throughout.
        s.wrench[2] = -8.0;
        m.push(&s);
    }
    let r = m.summary();
    assert_eq!(r.settling_time_s, None);
    assert_eq!(r.force_overshoot_pct, 0.0);
    assert!((r.force_rms_error_last_n - 2.0).abs() < 1e-12);
}
