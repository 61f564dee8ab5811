//! Tests of `armdyn::optimal::box_qp`: the box-constrained QP: the Newton step inside the box,
//! a binding bound held, and an indefinite Hessian reported.

use armdyn::optimal::box_qp::*;
use nalgebra::{DMatrix, DVector};

#[test]
fn unconstrained_minimum_inside_the_box_is_the_newton_step() {
    let h = DMatrix::from_row_slice(2, 2, &[4.0, 1.0, 1.0, 3.0]);
    let g = DVector::from_vec(vec![1.0, -2.0]);
    let inf = DVector::from_element(2, 1e9);
    let s = solve(&h, &g, &(-&inf), &inf, &DVector::zeros(2)).unwrap();
    let exact = h.clone().cholesky().unwrap().solve(&(-&g));
    assert!((s.x - exact).amax() < 1e-12);
    assert_eq!(s.free, vec![true, true]);
}

#[test]
fn a_bound_that_binds_is_held_and_the_rest_optimised() {
    // The unconstrained minimum (5/11, -9/11) violates x1 >= 0: x1 = 0 binds, and then
    // x0 = -(g0 + H01 x1) / H00 = 1/4.
    let h = DMatrix::from_row_slice(2, 2, &[4.0, 1.0, 1.0, 3.0]);
    let g = DVector::from_vec(vec![-1.0, 2.0]);
    let lo = DVector::from_vec(vec![-10.0, 0.0]);
    let hi = DVector::from_vec(vec![10.0, 10.0]);
    let s = solve(&h, &g, &lo, &hi, &DVector::from_vec(vec![5.0, 5.0])).unwrap();
    assert!((s.x[1]).abs() < 1e-15);
    assert!((s.x[0] - 0.25).abs() < 1e-12, "{}", s.x);
    assert_eq!(s.free, vec![true, false]);
    // KKT: the clamped variable's gradient pushes out of the box.
    let grad = &g + &h * &s.x;
    assert!(grad[1] > 0.0 && grad[0].abs() < 1e-12);
}

#[test]
fn an_indefinite_hessian_is_reported() {
    let h = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, -1.0]);
    let g = DVector::from_vec(vec![0.0, 0.0]);
    let one = DVector::from_element(2, 1.0);
    assert_eq!(
        solve(&h, &g, &(-&one), &one, &DVector::zeros(2)).unwrap_err(),
        BoxQpError::NotPositiveDefinite
    );
}
