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

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{Matrix4, SMatrix, Vector4};
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
}
