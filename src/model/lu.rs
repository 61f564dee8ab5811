//! Fixed-size LU factorisation with partial pivoting, `P A = L U`, and its solves, without
//! allocation, generic over the scalar (`f64`, and `f32` for the deployable step): the same
//! arithmetic, in the same order, as `nalgebra`'s [`nalgebra::linalg::LU`], so its results
//! are bit for bit nalgebra's.
//!
//! ```text
//! column i:  pivot p = argmax_{r >= i} |a_ri| (the first of equal ones); swap rows i and p;
//!            l_ri = a_ri * (1 / a_ii);   a_rk -= a_ik l_ri     (r, k > i)
//! A x = b:   b <- P b;  forward substitution with L (unit diagonal);  back substitution with U
//! A^T x = b: forward substitution with U^T;  back substitution with L^T;  x <- P^T x
//! |det A| = prod_i |u_ii|
//! ```
//!
//! Why not nalgebra's own: the SCARA's joint reference factorises a 4 x 4 Jacobian and
//! solves it twice at every control sample, and the full-frame force laws factorise the
//! 6 x 6 one at every step; nalgebra's generic implementation (views, a permutation
//! sequence, shape assertions) took 16 % of the 10 s thesis trial in a profile
//! (`docs/performance.md`). This one is written for one fixed size the compiler unrolls, and
//! is tested against nalgebra bit for bit.

use nalgebra::{RealField, SMatrix, SVector};

/// The LU factors of an `N x N` matrix (`L` below the diagonal with an implicit unit
/// diagonal, `U` on and above it) and the row swaps of the partial pivoting.
///
/// # Example
///
/// ```
/// use armdyn::model::lu::Lu;
/// use nalgebra::{Matrix2, Vector2};
///
/// let a = Matrix2::<f64>::new(1.0, 2.0, 3.0, 4.0);
/// let lu = Lu::new(&a);
/// assert!(lu.is_invertible());
/// let x = lu.solve(&Vector2::new(5.0, 6.0)).unwrap();
/// assert!((a * x - Vector2::new(5.0, 6.0)).norm() < 1e-14);
/// // Bit for bit nalgebra's:
/// assert_eq!(Some(x), a.lu().solve(&Vector2::new(5.0, 6.0)));
/// assert!((lu.det_abs() - 2.0).abs() < 1e-14);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lu<T: RealField + Copy, const N: usize> {
    /// `L` and `U` in one matrix, `m[r][c]` row `r`, column `c`.
    m: [[T; N]; N],
    /// Row swaps `(i, p)`, applied in order.
    swaps: [(usize, usize); N],
    /// How many of `swaps` are used.
    swap_count: usize,
}

impl<T: RealField + Copy, const N: usize> Lu<T, N> {
    /// Factorises `a`. A column without a non-zero entry on or below the diagonal is skipped
    /// (as nalgebra does): the factorisation exists, [`Self::is_invertible`] is false.
    #[inline]
    #[must_use]
    pub fn new(a: &SMatrix<T, N, N>) -> Self {
        Self::of_rows(core::array::from_fn(|r| {
            core::array::from_fn(|c| a[(r, c)])
        }))
    }

    /// [`Self::new`] of the matrix whose row `r` is `rows[r]`.
    #[inline]
    #[must_use]
    pub fn of_rows(rows: [[T; N]; N]) -> Self {
        let mut m = rows;
        let mut swaps = [(0, 0); N];
        let mut swap_count = 0;
        for i in 0..N {
            let mut pivot = i;
            let mut largest = m[i][i].abs();
            for (r, row) in m.iter().enumerate().skip(i + 1) {
                let v = row[i].abs();
                if v > largest {
                    largest = v;
                    pivot = r;
                }
            }
            let diag = m[pivot][i];
            if diag == T::zero() {
                continue;
            }
            if pivot != i {
                swaps[swap_count] = (i, pivot);
                swap_count += 1;
                m.swap(i, pivot);
            }
            let inv_diag = T::one() / diag;
            for row in m.iter_mut().skip(i + 1) {
                row[i] *= inv_diag;
            }
            let pivot_row = m[i];
            for row in m.iter_mut().skip(i + 1) {
                let l = row[i];
                for k in i + 1..N {
                    row[k] -= pivot_row[k] * l;
                }
            }
        }
        Self {
            m,
            swaps,
            swap_count,
        }
    }

    /// Whether every diagonal entry of `U` is non-zero (then [`Self::solve`] succeeds).
    #[inline]
    #[must_use]
    pub fn is_invertible(&self) -> bool {
        (0..N).all(|i| self.m[i][i] != T::zero())
    }

    /// `|det A| = prod_i |u_ii|` (0 for a skipped column, NaN for a non-finite `A`).
    #[inline]
    #[must_use]
    pub fn det_abs(&self) -> T {
        let mut d = T::one();
        for (i, row) in self.m.iter().enumerate() {
            d *= row[i].abs();
        }
        d
    }

    /// `x` with `A x = b`, or `None` if `U` has a zero on its diagonal. Non-finite entries
    /// propagate.
    #[inline]
    #[must_use]
    pub fn solve(&self, b: &SVector<T, N>) -> Option<SVector<T, N>> {
        let mut x = *b;
        for &(i, p) in &self.swaps[..self.swap_count] {
            x.swap_rows(i, p);
        }
        for i in 0..N.saturating_sub(1) {
            let coeff = x[i];
            for r in i + 1..N {
                x[r] -= coeff * self.m[r][i];
            }
        }
        for i in (0..N).rev() {
            let diag = self.m[i][i];
            if diag == T::zero() {
                return None;
            }
            let coeff = x[i] / diag;
            x[i] = coeff;
            for r in 0..i {
                x[r] -= coeff * self.m[r][i];
            }
        }
        Some(x)
    }

    /// `x` with `A^T x = b` (`A^T = U^T L^T P`), or `None` if `U` has a zero on its diagonal.
    #[inline]
    #[must_use]
    pub fn transpose_solve(&self, b: &SVector<T, N>) -> Option<SVector<T, N>> {
        let mut x = *b;
        for i in 0..N {
            let diag = self.m[i][i];
            if diag == T::zero() {
                return None;
            }
            let coeff = x[i] / diag;
            x[i] = coeff;
            for r in i + 1..N {
                x[r] -= coeff * self.m[i][r];
            }
        }
        for i in (1..N).rev() {
            let coeff = x[i];
            for r in 0..i {
                x[r] -= coeff * self.m[i][r];
            }
        }
        for &(i, p) in self.swaps[..self.swap_count].iter().rev() {
            x.swap_rows(i, p);
        }
        Some(x)
    }
}
