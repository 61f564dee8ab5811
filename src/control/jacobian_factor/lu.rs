//! Gaussian elimination with partial pivoting for a fixed-size square matrix: the exact
//! solve of [`JacobianFactor`](super::JacobianFactor) for N other than 4.

use nalgebra::{RealField, SVector};

/// `P A = L U` by Gaussian elimination with partial pivoting (Golub and Van Loan, alg.
/// 3.4.1), unrolled for a fixed `N`: `L` unit lower triangular below the diagonal of `lu`,
/// `U` on and above it, row `i` of `P A` being row `perm[i]` of `A`.
///
/// Rows are held as arrays (`lu[i]` is row `i`) and the pivot is brought up by swapping
/// with every lower row whose entry is larger (the largest ends up on top, as with an
/// argmax, on equal entries the upper one stays): no index is known only at run time, so
/// for a small `N` the whole elimination stays in registers.
#[derive(Clone, Copy, Debug)]
pub(super) struct Lu<T: RealField + Copy, const N: usize> {
    lu: [[T; N]; N],
    /// `1 / U_ii`.
    inv_diag: [T; N],
    perm: [usize; N],
    /// `|det A| = prod_i |U_ii|` (NaN for a non-finite `A`).
    pub(super) det_abs: T,
}

impl<T: RealField + Copy, const N: usize> Lu<T, N> {
    #[inline(always)]
    pub(super) fn new(a: [[T; N]; N]) -> Self {
        let mut lu = a;
        let mut perm = [0; N];
        for (i, p) in perm.iter_mut().enumerate() {
            *p = i;
        }
        let mut inv_diag = [T::zero(); N];
        let mut det_abs = T::one();
        for k in 0..N {
            for i in k + 1..N {
                if lu[i][k].abs() > lu[k][k].abs() {
                    lu.swap(k, i);
                    perm.swap(k, i);
                }
            }
            let d = lu[k][k];
            det_abs *= d.abs();
            // A zero pivot leaves a zero (then NaN) factor; det_abs = 0 sends it to the
            // damped branch, which never uses it.
            let inv = T::one() / d;
            inv_diag[k] = inv;
            let pivot_row = lu[k];
            for row in lu.iter_mut().skip(k + 1) {
                let l = row[k] * inv;
                row[k] = l;
                for j in k + 1..N {
                    row[j] -= l * pivot_row[j];
                }
            }
        }
        Self {
            lu,
            inv_diag,
            perm,
            det_abs,
        }
    }

    /// `x` with `A x = b`: `L y = P b`, then `U x = y`.
    #[inline(always)]
    pub(super) fn solve(&self, b: &SVector<T, N>) -> SVector<T, N> {
        let mut x = [T::zero(); N];
        for i in 0..N {
            let mut v = b[self.perm[i]];
            for (l, xk) in self.lu[i][..i].iter().zip(&x[..i]) {
                v -= *l * *xk;
            }
            x[i] = v;
        }
        for i in (0..N).rev() {
            let mut v = x[i];
            for (u, xk) in self.lu[i][i + 1..].iter().zip(&x[i + 1..]) {
                v -= *u * *xk;
            }
            x[i] = v * self.inv_diag[i];
        }
        SVector::<T, N>::from(x)
    }

    /// `x` with `A^T x = b`: `A^T = U^T L^T P`, so `U^T y = b`, `L^T z = y`, `x = P^T z`.
    #[inline]
    pub(super) fn transpose_solve(&self, b: &SVector<T, N>) -> SVector<T, N> {
        let mut y = [T::zero(); N];
        for i in 0..N {
            let mut v = b[i];
            for (row, yk) in self.lu[..i].iter().zip(&y[..i]) {
                v -= row[i] * *yk;
            }
            y[i] = v * self.inv_diag[i];
        }
        for i in (0..N).rev() {
            let mut v = y[i];
            for (row, yk) in self.lu[i + 1..].iter().zip(&y[i + 1..]) {
                v -= row[i] * *yk;
            }
            y[i] = v;
        }
        let mut x = SVector::<T, N>::zeros();
        for i in 0..N {
            x[self.perm[i]] = y[i];
        }
        x
    }
}
