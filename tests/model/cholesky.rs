//! Tests of `armdyn::model::cholesky`: the fixed-size Cholesky solve: a known system, and
//! indefinite or NaN matrices refused.

use armdyn::model::cholesky::*;
use armdyn::model::ModelError;
use nalgebra::{Matrix3, Vector3};

#[test]
fn solves_a_known_system() {
    let a = Matrix3::new(25.0, 15.0, -5.0, 15.0, 18.0, 0.0, -5.0, 0.0, 11.0);
    let chol = Cholesky::new(&a).unwrap();
    let expected_l = Matrix3::new(5.0, 0.0, 0.0, 3.0, 3.0, 0.0, -1.0, 1.0, 3.0);
    assert!((chol.l() - expected_l).norm() < 1e-14);
    let b = Vector3::new(1.0, -2.0, 3.0);
    let x = chol.solve(&b);
    assert!((a * x - b).norm() < 1e-13);
}

#[test]
fn rejects_indefinite_and_nan() {
    let a = Matrix3::new(1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0);
    assert!(matches!(
        Cholesky::new(&a),
        Err(ModelError::NotPositiveDefinite { index: 1, .. })
    ));
    let mut b = Matrix3::identity();
    b[(2, 0)] = f64::NAN;
    assert!(Cholesky::new(&b).is_err());
    let mut c = Matrix3::identity();
    c[(1, 1)] = f64::INFINITY;
    assert!(Cholesky::new(&c).is_err());
}
