//! Tests of `armdyn::identification::nonlinear`: the least-squares solver: an exponential fit,
//! and its evaluation budget never exceeded with the best point kept.

use armdyn::identification::nonlinear::*;
use nalgebra::{DMatrix, DVector};

#[test]
fn fits_an_exponential() {
    // r_k = a exp(b t_k) - y_k with y from a = 2, b = -0.7.
    let t: Vec<f64> = (0..20).map(|k| f64::from(k) * 0.2).collect();
    let y: Vec<f64> = t.iter().map(|t| 2.0 * libm::exp(-0.7 * t)).collect();
    let s = minimize(
        &DVector::from_vec(vec![1.0, 0.0]),
        &Stopping::tight(200),
        |x, jac| {
            let r = DVector::from_fn(t.len(), |k, _| x[0] * libm::exp(x[1] * t[k]) - y[k]);
            let j = jac.then(|| {
                DMatrix::from_fn(t.len(), 2, |k, c| {
                    let e = libm::exp(x[1] * t[k]);
                    if c == 0 {
                        e
                    } else {
                        x[0] * t[k] * e
                    }
                })
            });
            Some((r, j))
        },
    );
    assert!(s.converged, "{}", s.termination);
    approx::assert_relative_eq!(s.x[0], 2.0, epsilon = 1e-9);
    approx::assert_relative_eq!(s.x[1], -0.7, epsilon = 1e-9);
}

#[test]
fn the_budget_is_never_exceeded_and_the_best_point_is_kept() {
    // Rosenbrock's valley from far away: not solved in 3 evaluations.
    let model = |x: &DVector<f64>, jac: bool| {
        let r = DVector::from_vec(vec![10.0 * (x[1] - x[0] * x[0]), 1.0 - x[0]]);
        let j = jac.then(|| DMatrix::from_row_slice(2, 2, &[-20.0 * x[0], 10.0, -1.0, 0.0]));
        Some((r, j))
    };
    let x0 = DVector::from_vec(vec![-30.0, 40.0]);
    let mut calls = 0;
    let mut count = |done: usize, of: usize| {
        calls += 1;
        assert!(done <= of);
    };
    let s = minimize_reporting(&x0, &Stopping::tight(3), model, Some(&mut count));
    assert_eq!(s.termination, Termination::BudgetExhausted);
    assert!(!s.converged);
    assert_eq!((s.evaluations, s.budget, calls), (3, 3, 3));
    assert!(s.cost < s.initial_cost, "{} vs {}", s.cost, s.initial_cost);
    // With room, it converges, in far fewer evaluations than the crate's patience.
    let s = minimize(&x0, &Stopping::tight(400), model);
    assert!(s.converged, "{}", s.termination);
    assert!(s.evaluations < 400);
    approx::assert_relative_eq!(s.x[0], 1.0, epsilon = 1e-8);
}
