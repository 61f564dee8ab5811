//! Tests of `armdyn::identification::resample`: resampling a log: the time grid, interpolation
//! and derivatives exact on polynomials, and bad input refused.

use approx::assert_relative_eq;
use armdyn::identification::resample::*;

#[test]
fn grid_includes_end_on_the_grid() {
    let g = uniform_grid(0.5, 1.5, 1000.0).unwrap();
    assert_eq!(g.len(), 1001);
    assert_relative_eq!(g[0], 0.5);
    assert_relative_eq!(g[1000], 1.5, epsilon = 1e-12);
    // (0.3 - 0.1) * 10 = 1.9999999999999998: within 1e-9 of a period, included.
    assert_eq!(uniform_grid(0.1, 0.3, 10.0).unwrap().len(), 3);
    // Just short of the grid point: excluded.
    let g = uniform_grid(0.0, 0.2995, 10.0).unwrap();
    assert_eq!(g.len(), 3);
    assert_relative_eq!(g[2], 0.2);
    // A single point when start and end coincide.
    assert_eq!(uniform_grid(2.0, 2.0, 100.0).unwrap(), vec![2.0]);
}

#[test]
fn grid_rejects_bad_settings() {
    for rate in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            uniform_grid(0.0, 1.0, rate),
            Err(ResampleError::Rate { .. })
        ));
    }
    assert!(matches!(
        uniform_grid(1.0, 0.0, 10.0),
        Err(ResampleError::BadRange { .. })
    ));
    assert!(matches!(
        uniform_grid(f64::NAN, 1.0, 10.0),
        Err(ResampleError::BadRange { .. })
    ));
    assert!(matches!(
        uniform_grid(0.0, 1e30, 1e3),
        Err(ResampleError::GridTooLong { .. })
    ));
}

#[test]
fn interpolation_is_exact_on_a_linear_function() {
    let t = [0.0, 0.1, 0.25, 0.3, 0.7, 1.0];
    let x: Vec<f64> = t.iter().map(|t| 3.0 - 2.0 * t).collect();
    // Sorted, unsorted, on the samples and at both ends.
    let at = [0.0, 0.05, 0.25, 0.26, 0.5, 0.99, 1.0, 0.12, 0.0, 0.7];
    let y = interpolate_linear(&t, &x, &at).unwrap();
    for (a, y) in at.iter().zip(&y) {
        assert_relative_eq!(*y, 3.0 - 2.0 * a, epsilon = 1e-14);
    }
    // Sample values come back exactly.
    assert_eq!(interpolate_linear(&t, &x, &t).unwrap(), x);
    assert!(interpolate_linear(&t, &x, &[]).unwrap().is_empty());
}

#[test]
fn interpolation_rejects_times_outside_the_range() {
    let t = [0.0, 1.0, 2.0];
    let x = [0.0, 1.0, 4.0];
    let err = interpolate_linear(&t, &x, &[0.5, 2.5]).unwrap_err();
    assert_eq!(
        err,
        ResampleError::OutOfRange {
            index: 1,
            time: 2.5,
            first: 0.0,
            last: 2.0
        }
    );
    assert!(err.to_string().contains("2.5"), "{err}");
    assert!(matches!(
        interpolate_linear(&t, &x, &[-1e-9]),
        Err(ResampleError::OutOfRange { index: 0, .. })
    ));
    assert!(matches!(
        interpolate_linear(&t, &x, &[f64::NAN]),
        Err(ResampleError::OutOfRange { .. })
    ));
}

#[test]
fn interpolation_rejects_bad_samples() {
    let x = [0.0, 1.0, 2.0];
    let err = interpolate_linear(&[0.0, 1.0, 1.0], &x, &[0.5]).unwrap_err();
    assert_eq!(
        err,
        ResampleError::NotIncreasing {
            index: 2,
            t: 1.0,
            previous: 1.0
        }
    );
    assert!(err.to_string().contains("sample 2"), "{err}");
    assert!(matches!(
        interpolate_linear(&[0.0, 2.0, 1.0], &x, &[0.5]),
        Err(ResampleError::NotIncreasing { index: 2, .. })
    ));
    assert!(matches!(
        interpolate_linear(&[0.0, f64::NAN, 1.0], &x, &[0.5]),
        Err(ResampleError::NonFiniteTime { index: 1, .. })
    ));
    assert_eq!(
        interpolate_linear(&[0.0, 1.0], &x, &[0.5]),
        Err(ResampleError::LengthMismatch {
            times: 2,
            values: 3
        })
    );
    assert_eq!(
        interpolate_linear(&[0.0], &[1.0], &[0.0]),
        Err(ResampleError::TooFewSamples {
            needed: 2,
            count: 1
        })
    );
}

#[test]
fn derivative_is_exact_on_a_quadratic() {
    let dt = 0.01;
    // x = 2 + 3 t - 4 t², x' = 3 - 8 t, starting at t = 0.3.
    let t: Vec<f64> = (0..20).map(|k| 0.3 + f64::from(k) * dt).collect();
    let x: Vec<f64> = t.iter().map(|t| 2.0 + 3.0 * t - 4.0 * t * t).collect();
    let d = derivative(&x, dt).unwrap();
    assert_eq!(d.len(), x.len());
    for (t, d) in t.iter().zip(&d) {
        assert_relative_eq!(*d, 3.0 - 8.0 * t, epsilon = 1e-9);
    }
    // Three samples: all three from the same parabola.
    let d = derivative(&x[..3], dt).unwrap();
    for (t, d) in t.iter().zip(&d) {
        assert_relative_eq!(*d, 3.0 - 8.0 * t, epsilon = 1e-9);
    }
}

#[test]
fn derivative_rejects_bad_input() {
    assert_eq!(
        derivative(&[1.0, 2.0], 0.1),
        Err(ResampleError::TooFewSamples {
            needed: 3,
            count: 2
        })
    );
    for dt in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            derivative(&[1.0, 2.0, 3.0], dt),
            Err(ResampleError::Period { .. })
        ));
    }
}
