//! Tests of `armdyn::contact::sensor`: the force sensor: noise of the requested spread, reduced by
//! the filter; the bias adds, and a seed repeats.

use armdyn::contact::*;
use armdyn::model::Wrench;

#[test]
fn noise_has_the_requested_spread_and_the_filter_reduces_it() {
    let f = Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0);
    let spread = |cutoff| {
        let mut s = ForceSensor::new(Wrench::zeros(), Wrench::repeat(2.0), cutoff, 1).unwrap();
        let xs: [f64; 20_000] = core::array::from_fn(|_| s.measure(&f, 1e-3)[2]);
        let mean = xs.iter().sum::<f64>() / xs.len() as f64;
        (
            mean,
            libm::sqrt(xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / xs.len() as f64),
        )
    };
    let (mean, std) = spread(None);
    approx::assert_abs_diff_eq!(mean, -200.0, epsilon = 0.05);
    approx::assert_abs_diff_eq!(std, 2.0, epsilon = 0.05);
    // A first-order filter at 50 Hz sampled at 1 kHz keeps about sqrt(a / (2 - a)) of it.
    let (mean, std) = spread(Some(50.0));
    let a = 1e-3 / (1.0 / (2.0 * core::f64::consts::PI * 50.0) + 1e-3);
    let expected = 2.0 * libm::sqrt(a / (2.0 - a));
    approx::assert_abs_diff_eq!(mean, -200.0, epsilon = 0.05);
    approx::assert_relative_eq!(std, expected, max_relative = 0.05);
}

#[test]
fn bias_adds_and_same_seed_repeats() {
    let f = Wrench::zeros();
    let bias = Wrench::new(0.0, 0.0, 5.0, 0.0, 0.0, 0.0);
    let mut a = ForceSensor::new(bias, Wrench::repeat(1.0), None, 3).unwrap();
    let mut b = a.clone();
    let xa: [f64; 100] = core::array::from_fn(|_| a.measure(&f, 1e-3)[2]);
    let xb: [f64; 100] = core::array::from_fn(|_| b.measure(&f, 1e-3)[2]);
    assert_eq!(xa, xb);
    approx::assert_abs_diff_eq!(
        ForceSensor::new(bias, Wrench::zeros(), None, 0)
            .unwrap()
            .measure(&f, 1e-3)[2],
        5.0,
        epsilon = 1e-15
    );
    assert!(ForceSensor::new(bias, Wrench::repeat(-1.0), None, 0).is_err());
    assert!(ForceSensor::new(bias, Wrench::zeros(), Some(0.0), 0).is_err());
}
