//! The exact solve of a 4 x 4 [`JacobianFactor`](super::JacobianFactor) (the SCARA's and any
//! 4-joint robot's reduced Jacobian) in closed form, from the twelve 2 x 2 minors of its
//! upper and lower row pairs (Laplace expansion by complementary minors): no pivoting, so no
//! branch and no row moved through memory; one division.

use nalgebra::RealField;

/// A 4 x 4 matrix `A` with the 2 x 2 minors `s` of its rows 0, 1 and `c` of its rows 2, 3,
/// and `det A`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Minors4<T: RealField + Copy> {
    a: [[T; 4]; 4],
    /// Minors of rows 0, 1 on the column pairs (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
    s: [T; 6],
    /// Minors of rows 2, 3 on the column pairs (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
    c: [T; 6],
    inv_det: T,
    /// `|det A|` (NaN for a non-finite `A`).
    pub(super) det_abs: T,
}

/// `x0 y1 - x1 y0`.
#[inline(always)]
fn cross<T: RealField + Copy>(x0: T, x1: T, y0: T, y1: T) -> T {
    x0 * y1 - x1 * y0
}

impl<T: RealField + Copy> Minors4<T> {
    /// `A` given by rows.
    #[inline(always)]
    pub(super) fn new(a: [[T; 4]; 4]) -> Self {
        // Written out rather than by `array::map`, which a native build left as a call.
        let minors = |r: usize| {
            let m = |i: usize, j: usize| cross(a[r][i], a[r][j], a[r + 1][i], a[r + 1][j]);
            [m(0, 1), m(0, 2), m(0, 3), m(1, 2), m(1, 3), m(2, 3)]
        };
        let (s, c) = (minors(0), minors(2));
        // det A = sum over complementary column pairs, with the sign of the permutation.
        let det = s[0] * c[5] - s[1] * c[4] + s[2] * c[3] + s[3] * c[2] - s[4] * c[1] + s[5] * c[0];
        Self {
            a,
            s,
            c,
            inv_det: T::one() / det,
            det_abs: det.abs(),
        }
    }

    /// `x` with `A x = b`, by Cramer's rule: `det` of `A` with column `i` replaced by `b`,
    /// expanded by the minors of `b` with each column (`t` on rows 0, 1; `u` on rows 2, 3).
    #[inline(always)]
    pub(super) fn solve(&self, b: [T; 4]) -> [T; 4] {
        let (a, s, c) = (&self.a, &self.s, &self.c);
        let with_b = |r: usize| {
            let m = |j: usize| cross(b[r], b[r + 1], a[r][j], a[r + 1][j]);
            [m(0), m(1), m(2), m(3)]
        };
        let (t, u) = (with_b(0), with_b(2));
        let d = self.inv_det;
        [
            (c[5] * t[1] - c[4] * t[2] + c[3] * t[3] + s[5] * u[1] - s[4] * u[2] + s[3] * u[3]) * d,
            (-c[5] * t[0] + c[2] * t[2] - c[1] * t[3] - s[5] * u[0] + s[2] * u[2] - s[1] * u[3])
                * d,
            (c[4] * t[0] - c[2] * t[1] + c[0] * t[3] + s[4] * u[0] - s[2] * u[1] + s[0] * u[3]) * d,
            (-c[3] * t[0] + c[1] * t[1] - c[0] * t[2] - s[3] * u[0] + s[1] * u[1] - s[0] * u[2])
                * d,
        ]
    }

    /// `x` with `A^T x = b`: `x_j = sum_i (A^-1)_ij b_i`, with `A^-1 = adj(A) / det A` from
    /// the same minors.
    #[inline]
    pub(super) fn transpose_solve(&self, b: [T; 4]) -> [T; 4] {
        let (a, s, c) = (&self.a, &self.s, &self.c);
        let adj = [
            [
                a[1][1] * c[5] - a[1][2] * c[4] + a[1][3] * c[3],
                -a[0][1] * c[5] + a[0][2] * c[4] - a[0][3] * c[3],
                a[3][1] * s[5] - a[3][2] * s[4] + a[3][3] * s[3],
                -a[2][1] * s[5] + a[2][2] * s[4] - a[2][3] * s[3],
            ],
            [
                -a[1][0] * c[5] + a[1][2] * c[2] - a[1][3] * c[1],
                a[0][0] * c[5] - a[0][2] * c[2] + a[0][3] * c[1],
                -a[3][0] * s[5] + a[3][2] * s[2] - a[3][3] * s[1],
                a[2][0] * s[5] - a[2][2] * s[2] + a[2][3] * s[1],
            ],
            [
                a[1][0] * c[4] - a[1][1] * c[2] + a[1][3] * c[0],
                -a[0][0] * c[4] + a[0][1] * c[2] - a[0][3] * c[0],
                a[3][0] * s[4] - a[3][1] * s[2] + a[3][3] * s[0],
                -a[2][0] * s[4] + a[2][1] * s[2] - a[2][3] * s[0],
            ],
            [
                -a[1][0] * c[3] + a[1][1] * c[1] - a[1][2] * c[0],
                a[0][0] * c[3] - a[0][1] * c[1] + a[0][2] * c[0],
                -a[3][0] * s[3] + a[3][1] * s[1] - a[3][2] * s[0],
                a[2][0] * s[3] - a[2][1] * s[1] + a[2][2] * s[0],
            ],
        ];
        core::array::from_fn(|j| {
            (adj[0][j] * b[0] + adj[1][j] * b[1] + adj[2][j] * b[2] + adj[3][j] * b[3])
                * self.inv_det
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{Matrix4, Vector4};
    use rand::rngs::Xoshiro256PlusPlus;
    use rand::{RngExt, SeedableRng};

    #[test]
    fn the_minors_give_the_determinant_and_both_solves() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
        for _ in 0..1000 {
            let m = Matrix4::<f64>::from_fn(|_, _| rng.random_range(-2.0..2.0));
            let b = Vector4::<f64>::from_fn(|_, _| rng.random_range(-2.0..2.0));
            let f = Minors4::new(core::array::from_fn(|i| {
                core::array::from_fn(|j| m[(i, j)])
            }));
            assert_relative_eq!(f.det_abs, m.determinant().abs(), max_relative = 1e-10);
            let inv = m.try_inverse().unwrap();
            let scale = inv.norm() * b.norm();
            let x = Vector4::from(f.solve(b.into()));
            assert_relative_eq!(x, inv * b, epsilon = 1e-11 * scale);
            let y = Vector4::from(f.transpose_solve(b.into()));
            assert_relative_eq!(y, inv.transpose() * b, epsilon = 1e-11 * scale);
        }
    }
}
