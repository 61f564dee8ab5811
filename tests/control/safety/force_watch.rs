//! Tests of `armdyn::control::safety::force_watch`: the force watch: oscillation against a
//! constant error, the force rate over its window, and a loss only after an established
//! contact.

use armdyn::control::safety::force_watch::*;
use armdyn::control::safety::limits::defaults;
use armdyn::control::safety::{ForceLimits, TripCause};

fn limits() -> ForceLimits<f64> {
    ForceLimits {
        max_n: 500.0,
        max_rate_n_s: defaults::MAX_FORCE_RATE_N_S,
        rate_window_s: defaults::RATE_WINDOW_S,
        oscillation_rms_n: Some(10.0),
        oscillation_hz: defaults::OSCILLATION_HZ,
        oscillation_window_s: defaults::OSCILLATION_WINDOW_S,
        oscillation_arm_s: 0.0,
        oscillation_swing_window_s: defaults::OSCILLATION_SWING_WINDOW_S,
        loss_fraction: Some(defaults::LOSS_FRACTION),
        loss_s: defaults::LOSS_S,
    }
}

#[test]
fn a_constant_error_is_no_oscillation_and_a_sustained_one_is() {
    let l = limits();
    let mut w = ForceWatch::default();
    for k in 0..2000 {
        assert!(w.step(&l, k as f64 * 1e-3, 40.0, 50.0, true, 1e-3).is_ok());
    }
    assert!(w.peak_rms() < 1e-6, "{}", w.peak_rms());
    // A step of the force (200 N down in 50 ms) is one swing, not an oscillation.
    let mut w = ForceWatch::default();
    for k in 0..2000 {
        let t = k as f64 * 1e-3;
        let f = if t < 1.0 {
            50.0
        } else {
            50.0 + 200.0 * ((t - 1.0) / 0.05).min(1.0)
        };
        assert!(w.step(&l, t, f, 50.0, true, 1e-3).is_ok(), "{t}");
    }
    assert!(w.peak_rms() > 10.0);
    // 20 Hz, 20 N amplitude (RMS 14 N): trips within a few cycles.
    let mut w = ForceWatch::default();
    let trip = (0..2000)
        .find_map(|k| {
            let t = k as f64 * 1e-3;
            let f = 50.0 + 20.0 * (2.0 * core::f64::consts::PI * 20.0 * t).sin();
            w.step(&l, t, f, 50.0, true, 1e-3).err()
        })
        .unwrap();
    assert_eq!(trip.cause, TripCause::Oscillation);
    assert!(trip.t < 0.1, "{}", trip.t);
}

#[test]
fn the_rate_is_over_the_window_and_the_loss_needs_an_established_contact() {
    let mut l = limits();
    l.oscillation_rms_n = None;
    let mut w = ForceWatch::default();
    // A ramp of 10 kN/s passes; 30 kN/s trips.
    l.max_rate_n_s = 20_000.0;
    for k in 0..50 {
        assert!(w
            .step(&l, k as f64 * 1e-3, k as f64 * 10.0, 0.0, false, 1e-3)
            .is_ok());
    }
    approx::assert_relative_eq!(w.peak_rate(), 10_000.0, max_relative = 1e-9);
    let mut w = ForceWatch::default();
    let trip = (0..50)
        .find_map(|k| {
            w.step(&l, k as f64 * 1e-3, k as f64 * 30.0, 0.0, false, 1e-3)
                .err()
        })
        .unwrap();
    assert_eq!((trip.cause, trip.t), (TripCause::ForceRate, 0.01));
    // No contact yet: no loss; after contact, 2 ms below 20 % trips.
    let mut w = ForceWatch::default();
    for k in 0..100 {
        assert!(w.step(&l, k as f64 * 1e-3, 0.0, 50.0, true, 1e-3).is_ok());
    }
    assert!(w.step(&l, 0.1, 50.0, 50.0, true, 1e-3).is_ok());
    let trip = (0..10)
        .find_map(|k| {
            w.step(&l, 0.101 + k as f64 * 1e-3, 1.0, 50.0, true, 1e-3)
                .err()
        })
        .unwrap();
    assert_eq!(trip.cause, TripCause::ContactLost);
    approx::assert_abs_diff_eq!(trip.t, 0.102, epsilon = 1e-12);
}
