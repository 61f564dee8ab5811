//! Tests of `armdyn::model::lu`: the fixed-size LU: nalgebra's LU bit for bit, the transposed
//! solve and the determinant, and a singular matrix without solution.

use approx::assert_relative_eq;
use armdyn::model::lu::*;
use nalgebra::{Matrix4, SMatrix, SVector, Vector4};
use rand::rngs::Xoshiro256PlusPlus as StdRng;
use rand::{RngExt, SeedableRng};

/// Our solve against nalgebra's, bit for bit (a macro: nalgebra's LU needs
/// typenum bounds a const-generic helper cannot name).
macro_rules! same_bits {
    ($a:expr, $b:expr) => {{
        let (a, b) = ($a, $b);
        let ours = Lu::new(&a);
        let theirs = a.lu();
        assert_eq!(ours.is_invertible(), theirs.is_invertible(), "{a}");
        let (x, y) = (ours.solve(&b), theirs.solve(&b));
        assert_eq!(x.is_some(), y.is_some(), "{a}");
        if let (Some(x), Some(y)) = (x, y) {
            for (u, v) in x.iter().zip(y.iter()) {
                assert!(
                    u.to_bits() == v.to_bits() || (u.is_nan() && v.is_nan()),
                    "{a} {x} {y}"
                );
            }
        }
    }};
}

#[test]
fn is_nalgebras_lu_bit_for_bit() {
    let mut rng = StdRng::seed_from_u64(7);
    for trial in 0..20_000 {
        let mut a = Matrix4::from_fn(|_, _| rng.random_range(-2.0..2.0));
        // Ties, zeros, repeated rows and special values exercise every branch.
        match trial % 8 {
            1 => a.set_column(0, &Vector4::zeros()),
            2 => a[(1, 0)] = -a[(0, 0)],
            3 => {
                let r = a.row(0).clone_owned();
                a.set_row(2, &r);
            }
            4 => a[(trial % 4, (trial / 4) % 4)] = f64::NAN,
            5 => a[(2, 3)] = f64::INFINITY,
            6 => a = a.map(|x| (x * 2.0).round()),
            _ => {}
        }
        let b = Vector4::from_fn(|_, _| rng.random_range(-5.0..5.0));
        same_bits!(a, b);
    }
    for _ in 0..2_000 {
        let a = SMatrix::<f64, 6, 6>::from_fn(|_, _| rng.random_range(-1.0..1.0));
        let b = SVector::<f64, 6>::from_fn(|_, _| rng.random_range(-1.0..1.0));
        same_bits!(a, b);
    }
}

#[test]
fn solves_the_transposed_system_and_gives_the_determinant() {
    let mut rng = StdRng::seed_from_u64(11);
    for _ in 0..200 {
        let a = SMatrix::<f64, 6, 6>::from_fn(|_, _| rng.random_range(-1.0..1.0));
        let b = SVector::<f64, 6>::from_fn(|_, _| rng.random_range(-1.0..1.0));
        let lu = Lu::new(&a);
        let x = lu.transpose_solve(&b).unwrap();
        assert!(
            (a.transpose() * x - b).norm() < 1e-9 * (1.0 + x.norm()),
            "{a}"
        );
        assert_relative_eq!(lu.det_abs(), a.determinant().abs(), max_relative = 1e-10);
    }
    // A matrix that needs pivoting at every step, in f64 and in f32.
    let a = Matrix4::<f64>::new(
        0.0, 2.0, -1.0, 3.0, //
        1e-3, 0.5, 4.0, -2.0, //
        -5.0, 1.0, 0.25, 0.0, //
        2.0, -3.0, 1.0, 7.0,
    );
    let b = Vector4::new(1.0, -2.0, 0.5, 3.0);
    let lu = Lu::new(&a);
    assert_relative_eq!(lu.det_abs(), a.determinant().abs(), max_relative = 1e-14);
    assert_relative_eq!(
        a.transpose() * lu.transpose_solve(&b).unwrap(),
        b,
        epsilon = 1e-14
    );
    let (a32, b32) = (a.map(|x| x as f32), b.map(|x| x as f32));
    let lu32 = Lu::new(&a32);
    assert_relative_eq!(a32 * lu32.solve(&b32).unwrap(), b32, epsilon = 1e-5);
    assert_relative_eq!(
        a32.transpose() * lu32.transpose_solve(&b32).unwrap(),
        b32,
        epsilon = 1e-5
    );
}

#[test]
fn a_singular_matrix_has_no_solution() {
    let a = Matrix4::new(
        1.0, 2.0, 0.0, 0.0, 2.0, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    );
    let lu = Lu::new(&a);
    assert!(!lu.is_invertible());
    assert_eq!(lu.det_abs(), 0.0);
    assert_eq!(lu.solve(&Vector4::repeat(1.0)), None);
    assert_eq!(lu.transpose_solve(&Vector4::repeat(1.0)), None);
}
