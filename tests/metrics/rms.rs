//! `metrics/rms.rs`: the running RMS and maximum.

use armdyn::metrics::{Rms, RmsMax};
use std::f64::consts::PI;

#[test]
fn rms_and_max_of_a_series_and_zeros_without_one() {
    let mut a = RmsMax::default();
    assert_eq!((a.rms(), a.max(), a.count()), (0.0, 0.0, 0));
    for x in [3.0, 4.0, 0.0] {
        a.push(x);
    }
    assert!((a.rms() - (25.0_f64 / 3.0).sqrt()).abs() < 1e-15);
    assert_eq!((a.max(), a.count()), (4.0, 3));
}

#[test]
fn the_rms_of_a_sine_over_whole_periods_is_its_amplitude_over_root_two() {
    let mut a = Rms::default();
    let n = 1000;
    for k in 0..3 * n {
        a.push(2.5 * (2.0 * PI * k as f64 / n as f64 + 0.3).sin());
    }
    assert!(
        (a.rms() - 2.5 / 2.0_f64.sqrt()).abs() < 1e-12,
        "{}",
        a.rms()
    );
    assert_eq!(a.count(), 3 * n);
}

#[test]
fn a_value_given_by_its_square_counts_as_the_value() {
    let (mut by_value, mut by_square) = (Rms::default(), Rms::default());
    for (x, y) in [(3.0, 4.0), (-1.0, 2.0), (0.5, -0.25)] {
        by_value.push(f64::hypot(x, y));
        by_square.push_squared(x * x + y * y);
    }
    assert!((by_value.rms() - by_square.rms()).abs() < 1e-15);
    // The sign of a value does not count.
    let mut signed = Rms::default();
    signed.push(-3.0);
    signed.push(3.0);
    assert_eq!(signed.rms(), 3.0);
    assert_eq!(Rms::default().rms(), 0.0);
}
