//! Fixed-size LU factorisation with partial pivoting, `P A = L U`, and its solve, without
//! allocation: the same arithmetic, in the same order, as `nalgebra`'s
//! [`nalgebra::linalg::LU`], so its results are bit for bit nalgebra's.
//!
//! ```text
//! column i:  pivot p = argmax_{r >= i} |a_ri| (the first of equal ones); swap rows i and p;
//!            l_ri = a_ri * (1 / a_ii);   a_rk -= a_ik l_ri     (r, k > i)
//! solve:     b <- P b;  forward substitution with L (unit diagonal);  back substitution with U
//! ```
//!
//! Why not nalgebra's own: the SCARA's joint reference factorises a 4 x 4 Jacobian and
//! solves it twice at every control sample, and nalgebra's generic implementation (views,
//! a permutation sequence, shape assertions) took 16 % of the 10 s thesis trial in a profile
//! (`docs/performance.md`). This one is written for one fixed size the compiler unrolls, and
//! is tested against nalgebra bit for bit, so the trial's outputs did not change.

use nalgebra::{SMatrix, SVector};

/// The LU factors of an `N x N` matrix (`L` below the diagonal with an implicit unit
/// diagonal, `U` on and above it) and the row swaps of the partial pivoting.
///
/// # Example
///
/// ```
/// use armdyn::model::lu::Lu;
/// use nalgebra::{Matrix2, Vector2};
///
/// let a = Matrix2::new(1.0, 2.0, 3.0, 4.0);
/// let lu = Lu::new(&a);
/// assert!(lu.is_invertible());
/// let x = lu.solve(&Vector2::new(5.0, 6.0)).unwrap();
/// assert!((a * x - Vector2::new(5.0, 6.0)).norm() < 1e-14);
/// // Bit for bit nalgebra's:
/// assert_eq!(Some(x), a.lu().solve(&Vector2::new(5.0, 6.0)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lu<const N: usize> {
    /// `L` and `U` in one matrix, `m[r][c]` row `r`, column `c`.
    m: [[f64; N]; N],
    /// Row swaps `(i, p)`, applied in order.
    swaps: [(usize, usize); N],
    /// How many of `swaps` are used.
    swap_count: usize,
}

impl<const N: usize> Lu<N> {
    /// Factorises `a`. A column without a non-zero entry on or below the diagonal is skipped
    /// (as nalgebra does): the factorisation exists, [`Self::is_invertible`] is false.
    #[inline]
    #[must_use]
    pub fn new(a: &SMatrix<f64, N, N>) -> Self {
        let mut m = [[0.0; N]; N];
        for (r, row) in m.iter_mut().enumerate() {
            for (c, x) in row.iter_mut().enumerate() {
                *x = a[(r, c)];
            }
        }
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
            if diag == 0.0 {
                continue;
            }
            if pivot != i {
                swaps[swap_count] = (i, pivot);
                swap_count += 1;
                m.swap(i, pivot);
            }
            let inv_diag = 1.0 / diag;
            for row in m.iter_mut().skip(i + 1) {
                row[i] *= inv_diag;
            }
            for k in i + 1..N {
                let p = m[i][k];
                for r in i + 1..N {
                    m[r][k] -= p * m[r][i];
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
        (0..N).all(|i| self.m[i][i] != 0.0)
    }

    /// `x` with `A x = b`, or `None` if `U` has a zero on its diagonal. Non-finite entries
    /// propagate.
    #[inline]
    #[must_use]
    pub fn solve(&self, b: &SVector<f64, N>) -> Option<SVector<f64, N>> {
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
            if diag == 0.0 {
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
}

#[cfg(test)]
mod tests {
    use super::*;
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
    fn a_singular_matrix_has_no_solution() {
        let a = Matrix4::new(
            1.0, 2.0, 0.0, 0.0, 2.0, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        );
        let lu = Lu::new(&a);
        assert!(!lu.is_invertible());
        assert_eq!(lu.solve(&Vector4::repeat(1.0)), None);
    }
}
