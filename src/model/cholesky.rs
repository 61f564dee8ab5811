//! Fixed-size Cholesky factorisation `A = L L^T` and solve, without allocation.
//!
//! Used by [`forward_dynamics`](super::forward_dynamics) to solve `M qdd = rhs`; the mass
//! matrix is symmetric positive definite for any physical robot.

use nalgebra::{SMatrix, SVector};

use super::error::ModelError;

/// The Cholesky factor `L` (lower triangular, positive diagonal) of an `N x N` symmetric
/// positive-definite matrix.
///
/// # Example
///
/// ```
/// use scara::model::cholesky::Cholesky;
/// use nalgebra::{Matrix2, Vector2};
///
/// let a = Matrix2::new(4.0, 2.0, 2.0, 3.0);
/// let x = Cholesky::new(&a).unwrap().solve(&Vector2::new(2.0, 1.0));
/// assert!((a * x - Vector2::new(2.0, 1.0)).norm() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cholesky<const N: usize> {
    l: SMatrix<f64, N, N>,
}

impl<const N: usize> Cholesky<N> {
    /// Factorises `a`, reading only its lower triangle (the matrix is assumed symmetric;
    /// symmetry is not checked).
    ///
    /// # Errors
    ///
    /// [`ModelError::NotPositiveDefinite`] if a pivot is not positive, or not finite (any
    /// NaN or infinity in the lower triangle ends up in a pivot).
    pub fn new(a: &SMatrix<f64, N, N>) -> Result<Self, ModelError> {
        let mut l = SMatrix::<f64, N, N>::zeros();
        for j in 0..N {
            let mut pivot = a[(j, j)];
            for k in 0..j {
                pivot -= l[(j, k)] * l[(j, k)];
            }
            // NaN fails both comparisons, so it is refused too.
            let positive = pivot > 0.0 && pivot.is_finite();
            if !positive {
                return Err(ModelError::NotPositiveDefinite { index: j, pivot });
            }
            let diag = libm::sqrt(pivot);
            l[(j, j)] = diag;
            for i in (j + 1)..N {
                let mut s = a[(i, j)];
                for k in 0..j {
                    s -= l[(i, k)] * l[(j, k)];
                }
                l[(i, j)] = s / diag;
            }
        }
        // A NaN off the diagonal below the last pivot would not reach a pivot; refuse it.
        for i in 0..N {
            for k in 0..i {
                if !l[(i, k)].is_finite() {
                    return Err(ModelError::NotPositiveDefinite {
                        index: i,
                        pivot: l[(i, k)],
                    });
                }
            }
        }
        Ok(Self { l })
    }

    /// The lower-triangular factor `L`, with `A = L L^T`.
    pub fn l(&self) -> &SMatrix<f64, N, N> {
        &self.l
    }

    /// Solves `A x = b` by forward then backward substitution.
    pub fn solve(&self, b: &SVector<f64, N>) -> SVector<f64, N> {
        let l = &self.l;
        // L y = b
        let mut y = *b;
        for i in 0..N {
            let mut s = y[i];
            for k in 0..i {
                s -= l[(i, k)] * y[k];
            }
            y[i] = s / l[(i, i)];
        }
        // L^T x = y
        let mut x = y;
        for i in (0..N).rev() {
            let mut s = x[i];
            for k in (i + 1)..N {
                s -= l[(k, i)] * x[k];
            }
            x[i] = s / l[(i, i)];
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
}
