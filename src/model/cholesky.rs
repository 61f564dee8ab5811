//! Fixed-size Cholesky factorisation `A = L L^T` and solve, without allocation.
//!
//! A thin layer over `nalgebra`'s fixed-size [`nalgebra::linalg::Cholesky`] (its square
//! root is `f64::sqrt` with `std`, the hardware instruction in every build) that refuses
//! non-positive and non-finite pivots and says which one failed. Used by the hybrid
//! controller's Jacobian solve and by [`forward_dynamics_cholesky`](super::forward_dynamics_cholesky).

use nalgebra::{Const, SMatrix, SVector};

use super::error::ModelError;

/// The Cholesky factor `L` (lower triangular, positive diagonal) of an `N x N` symmetric
/// positive-definite matrix.
///
/// # Example
///
/// ```
/// use armdyn::model::cholesky::Cholesky;
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
    #[inline]
    pub fn new(a: &SMatrix<f64, N, N>) -> Result<Self, ModelError> {
        if let Some(c) = nalgebra::linalg::Cholesky::<f64, Const<N>>::new(*a) {
            // nalgebra takes the square root of a zero pivot and divides by it, and a NaN
            // off the diagonal of row i reaches pivot i; so a factor whose diagonal is
            // positive and finite and whose entries are finite is a valid one.
            let l = c.unpack();
            let valid = (0..N).all(|i| {
                let d = l[(i, i)];
                d > 0.0 && d.is_finite() && (0..i).all(|k| l[(i, k)].is_finite())
            });
            if valid {
                return Ok(Self { l });
            }
        }
        Err(first_failing_pivot(a))
    }

    /// The lower-triangular factor `L`, with `A = L L^T`.
    pub fn l(&self) -> &SMatrix<f64, N, N> {
        &self.l
    }

    /// Solves `A x = b` by forward then backward substitution.
    #[inline]
    pub fn solve(&self, b: &SVector<f64, N>) -> SVector<f64, N> {
        let mut x = *b;
        // Both read only the lower triangle of `l`, whose diagonal is non-zero.
        self.l.solve_lower_triangular_unchecked_mut(&mut x);
        self.l.tr_solve_lower_triangular_unchecked_mut(&mut x);
        x
    }
}

/// The error of a refused factorisation: the first row whose pivot is not positive and
/// finite (or, failing that, the first non-finite entry of the factor), recomputed on this
/// cold path by the textbook algorithm.
#[cold]
fn first_failing_pivot<const N: usize>(a: &SMatrix<f64, N, N>) -> ModelError {
    let mut l = SMatrix::<f64, N, N>::zeros();
    for j in 0..N {
        let mut pivot = a[(j, j)];
        for k in 0..j {
            pivot -= l[(j, k)] * l[(j, k)];
        }
        // NaN fails both comparisons, so it is refused too.
        if !(pivot > 0.0 && pivot.is_finite()) {
            return ModelError::NotPositiveDefinite { index: j, pivot };
        }
        let diag = crate::math::sqrt(pivot);
        l[(j, j)] = diag;
        for i in (j + 1)..N {
            let mut s = a[(i, j)];
            for k in 0..j {
                s -= l[(i, k)] * l[(j, k)];
            }
            l[(i, j)] = s / diag;
        }
    }
    for i in 0..N {
        for k in 0..i {
            if !l[(i, k)].is_finite() {
                return ModelError::NotPositiveDefinite {
                    index: i,
                    pivot: l[(i, k)],
                };
            }
        }
    }
    // Reached only if the two algorithms round differently at a pivot that is zero to
    // within rounding: nalgebra refused it, the textbook order did not.
    ModelError::NotPositiveDefinite {
        index: N.saturating_sub(1),
        pivot: f64::NAN,
    }
}
