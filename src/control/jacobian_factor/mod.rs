//! The solve of the reduced (square) Jacobian `J_r` behind the hybrid and admittance
//! controllers: `J_r dq = dx` and `J_r^T f = tau`, exact away from singularities and damped
//! least squares near them. Generic over the scalar, so the deployable `f32` step
//! ([`crate::robots::scara::deploy`]) runs the very same algorithm.

mod minors4;

use crate::model::lu::Lu;
use minors4::Minors4;
use nalgebra::{RealField, SMatrix, SVector};

/// How `J^-T` was obtained at the last step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JacobianSolve {
    /// `S` selected every task direction for position: `J^T S J^-T = I`, no inverse needed.
    NotNeeded,
    /// Exact solve: the closed form of a 4 x 4 `J_r`, LU with partial pivoting otherwise.
    Exact,
    /// Near a singularity: damped least squares (see [`reduced_transpose_solve`]).
    Damped,
}

/// Below this normalised determinant of the reduced Jacobian (|det J| over the product of
/// its row norms, 1 for orthogonal rows, 0 at a singularity) the solve is damped.
pub const SINGULARITY_THRESHOLD: f64 = 1e-3;
/// Largest damping `lambda` (same units as the Jacobian entries, m or 1) at the singularity.
pub const MAX_DAMPING: f64 = 1e-2;

/// Solves `J_r^T f = tau` for the task wrench `f` (N x N reduced Jacobian).
///
/// Away from singularities (normalised determinant `m = |det J_r| / prod_i |row_i J_r|`
/// at or above [`SINGULARITY_THRESHOLD`]) `f = J_r^-T tau`, exactly ([`JacobianFactor`]: the
/// 2 x 2 minors of a 4 x 4 `J_r`, an LU factorisation otherwise; both also give `det J_r`).
/// Closer, damped least squares
/// `f = J_r (J_r^T J_r + lambda^2 I)^-1 tau` by a Cholesky factorisation, with
/// `lambda = MAX_DAMPING (1 - m / SINGULARITY_THRESHOLD)`, growing smoothly from 0 at the
/// threshold, so the wrench stays bounded instead of the thesis's nudge of `q2` by 1e-4.
#[must_use]
pub fn reduced_transpose_solve<T: RealField + Copy, const N: usize>(
    jr: &SMatrix<T, N, N>,
    tau: &SVector<T, N>,
) -> (SVector<T, N>, JacobianSolve) {
    let f = JacobianFactor::new(jr);
    (f.transpose_solve(tau), f.how())
}

/// The factorisation behind [`reduced_transpose_solve`], kept to solve both
/// `J_r^T f = tau` and `J_r dq = dx` at one state, for any right-hand side: the minors or
/// the LU factors of `J_r`, or near a singularity the damped pseudo-inverse
/// `P = (J_r^T J_r + lambda^2 I)^-1 J_r^T` (`dq = P dx`, `f = P^T tau`), zero if even the
/// damped system could not be factorised (a non-finite Jacobian).
///
/// Units: the solves map task-space quantities (m, rad, N, N m) to joint-space ones (rad,
/// m, N m, N), the inverse of the Jacobian's.
///
/// The exact solve is, for N = 4, Cramer's rule on the 2 x 2 minors (`minors4`: no
/// pivoting, no branch, one division), and otherwise Gaussian elimination with partial
/// pivoting (`lu`). Both are written here rather than taken from nalgebra (`LU`, whose
/// elimination runs on dynamically sized views, or `try_inverse`, which forms all of
/// `J_r^-1`): the hybrid step needs one solve and `det J_r`, and was measured faster so
/// (`cargo bench --bench control`, `step/hybrid-pi-ff`).
#[derive(Clone, Copy, Debug)]
pub struct JacobianFactor<T: RealField + Copy, const N: usize> {
    factor: Factor<T, N>,
}

#[derive(Clone, Copy, Debug)]
enum Factor<T: RealField + Copy, const N: usize> {
    /// Chosen only for `|det J_r| > 0`: its solves do not fail.
    Exact(Lu<T, N>),
    /// N = 4.
    Exact4(Minors4<T>),
    /// `P` and `J_r^T P^T`.
    Damped(SMatrix<T, N, N>, SMatrix<T, N, N>),
}

impl<T: RealField + Copy, const N: usize> JacobianFactor<T, N> {
    /// Factorises, damped near singularities as [`reduced_transpose_solve`] says.
    #[must_use]
    #[inline(always)]
    pub fn new(jr: &SMatrix<T, N, N>) -> Self {
        let mut a = [[T::zero(); N]; N];
        for (i, row) in a.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x = jr[(i, j)];
            }
        }
        Self::factorise(a)
    }

    /// Factorises the reduced Jacobian made of the rows `rows` of the 6 x N Jacobian `j`
    /// (each in 0..6), as [`Self::new`] does that matrix; reads `j` entry by entry, with no
    /// copy of the reduced matrix in memory.
    #[must_use]
    #[inline(always)]
    pub fn from_rows(j: &SMatrix<T, 6, N>, rows: &[usize; N]) -> Self {
        let mut a = [[T::zero(); N]; N];
        for (row, &k) in a.iter_mut().zip(rows) {
            for (c, x) in row.iter_mut().enumerate() {
                *x = j[(k, c)];
            }
        }
        Self::factorise(a)
    }

    /// The test `m >= SINGULARITY_THRESHOLD` is made squared, `det^2 >= t^2 prod_i
    /// |row_i|^2`, without a square root; a NaN fails it and is damped (to zero).
    #[inline(always)]
    fn factorise(a: [[T; N]; N]) -> Self {
        // Product of the squared row norms of J_r (the denominator of m, squared).
        let mut rows_sq = T::one();
        for row in &a {
            let mut s = T::zero();
            for x in row {
                s += *x * *x;
            }
            rows_sq *= s;
        }
        let (exact, det_abs) = if N == 4 {
            let m = Minors4::new(core::array::from_fn(|i| core::array::from_fn(|j| a[i][j])));
            (Factor::Exact4(m), m.det_abs)
        } else {
            let lu = Lu::of_rows(a);
            (Factor::Exact(lu), lu.det_abs())
        };
        let det_sq = det_abs * det_abs;
        let t: T = nalgebra::convert(SINGULARITY_THRESHOLD);
        if det_sq >= t * t * rows_sq && rows_sq > T::zero() {
            return Self { factor: exact };
        }
        Self::damped(
            &SMatrix::<T, N, N>::from_fn(|r, c| a[r][c]),
            normalised(det_abs, rows_sq),
            t,
        )
    }

    /// `P = (J_r^T J_r + lambda^2 I)^-1 J_r^T` and `J_r^T P^T` for the normalised
    /// determinant `m` below the threshold `t`; zero if the Cholesky factorisation fails.
    #[cold]
    #[inline(never)]
    fn damped(jr: &SMatrix<T, N, N>, m: T, t: T) -> Self {
        let max_damping: T = nalgebra::convert(MAX_DAMPING);
        let lambda = max_damping * (T::one() - m / t);
        let floor = min_positive::<T>();
        let a = jr.transpose() * jr + SMatrix::<T, N, N>::identity() * (lambda * lambda).max(floor);
        let p = match cholesky(&a) {
            Some(c) => {
                let mut p = jr.transpose();
                c.solve_mut(&mut p);
                p
            }
            None => SMatrix::<T, N, N>::zeros(),
        };
        Self {
            factor: Factor::Damped(p, jr.tr_mul(&p.transpose())),
        }
    }

    /// How the factor was obtained: [`JacobianSolve::Exact`] or [`JacobianSolve::Damped`].
    #[must_use]
    pub fn how(&self) -> JacobianSolve {
        match self.factor {
            Factor::Exact(_) | Factor::Exact4(_) => JacobianSolve::Exact,
            Factor::Damped(..) => JacobianSolve::Damped,
        }
    }

    /// The task wrench `f` with `J_r^T f = tau` (least squares, damped alike; zero if even
    /// the damped system failed).
    #[must_use]
    #[inline]
    pub fn transpose_solve(&self, tau: &SVector<T, N>) -> SVector<T, N> {
        match &self.factor {
            Factor::Exact(lu) => lu.transpose_solve(tau).unwrap_or_else(SVector::zeros),
            Factor::Exact4(m) => from4(m.transpose_solve(to4(tau))),
            Factor::Damped(p, _) => p.tr_mul(tau),
        }
    }

    /// `J_r^T f` for the wrench `f` that [`Self::transpose_solve`] returns: `tau` itself when
    /// exact (`J_r^T J_r^-T = I`), `J_r^T J_r (J_r^T J_r + lambda^2 I)^-1 tau` when damped.
    #[must_use]
    #[inline]
    pub fn wrench_torque(&self, tau: &SVector<T, N>) -> SVector<T, N> {
        match &self.factor {
            Factor::Exact(_) | Factor::Exact4(_) => *tau,
            Factor::Damped(_, w) => w * tau,
        }
    }

    /// The joint displacement `dq` with `J_r dq = dx` (least squares, damped alike).
    #[must_use]
    #[inline(always)]
    pub fn solve(&self, dx: &SVector<T, N>) -> SVector<T, N> {
        match &self.factor {
            Factor::Exact(lu) => lu.solve(dx).unwrap_or_else(SVector::zeros),
            Factor::Exact4(m) => from4(m.solve(to4(dx))),
            Factor::Damped(p, _) => p * dx,
        }
    }
}

/// The smallest positive normal number of `T` (`f64`'s, or `f32`'s, to which `f64`'s rounds
/// to zero).
fn min_positive<T: RealField + Copy>() -> T {
    let double: T = nalgebra::convert(f64::MIN_POSITIVE);
    if double > T::zero() {
        double
    } else {
        nalgebra::convert(f64::from(f32::MIN_POSITIVE))
    }
}

/// The first four entries of `v` (only called with N = 4).
#[inline(always)]
fn to4<T: RealField + Copy, const N: usize>(v: &SVector<T, N>) -> [T; 4] {
    core::array::from_fn(|i| if i < N { v[i] } else { T::zero() })
}

/// `x` as an N-vector (only called with N = 4).
#[inline(always)]
fn from4<T: RealField + Copy, const N: usize>(x: [T; 4]) -> SVector<T, N> {
    SVector::<T, N>::from_fn(|i, _| if i < 4 { x[i] } else { T::zero() })
}

/// `m = |det J_r| / sqrt(rows_sq)`, 0 where it is not a finite number or a row is zero.
#[cold]
fn normalised<T: RealField + Copy>(det_abs: T, rows_sq: T) -> T {
    let m = det_abs / rows_sq.sqrt();
    if rows_sq > T::zero() && m.is_finite() {
        m
    } else {
        T::zero()
    }
}

/// nalgebra's Cholesky factorisation of `a`, if every pivot is positive and finite and every
/// entry finite (nalgebra takes the square root of a zero pivot and divides by it).
fn cholesky<T: RealField + Copy, const N: usize>(
    a: &SMatrix<T, N, N>,
) -> Option<nalgebra::linalg::Cholesky<T, nalgebra::Const<N>>> {
    let c = nalgebra::linalg::Cholesky::new(*a)?;
    let l = c.l_dirty();
    let valid = (0..N).all(|i| {
        let d = l[(i, i)];
        d > T::zero() && d.is_finite() && (0..i).all(|k| l[(i, k)].is_finite())
    });
    valid.then_some(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{JointMatrix, JointVector, RobotModel, Scara};
    use approx::assert_relative_eq;

    /// The reduced SCARA Jacobian (rows vx vy vz wz) at `q`.
    fn jr(q: [f64; 4]) -> JointMatrix<4> {
        let j = Scara.jacobian(&JointVector::<4>::from(q));
        JointMatrix::<4>::from_fn(|r, c| j[([0, 1, 2, 5][r], c)])
    }

    /// `m` by its definition, with nalgebra's determinant.
    fn measure(jr: &JointMatrix<4>) -> f64 {
        let rows: f64 = (0..4).map(|i| jr.row(i).norm()).product();
        jr.determinant().abs() / rows
    }

    #[test]
    fn away_from_singularities_the_solves_are_exact() {
        let tau = JointVector::<4>::new(3.0, -2.0, 48.0, 0.5);
        // m = 0.008 at q2 = 0.02, still above the threshold.
        for q2 in [0.8, -2.0, 0.02] {
            let jr = jr([0.3, q2, 0.2, 0.1]);
            let f = JacobianFactor::new(&jr);
            assert_eq!(f.how(), JacobianSolve::Exact, "q2 = {q2}");
            let w = f.transpose_solve(&tau);
            assert!((jr.transpose() * w - tau).norm() < 1e-12 * tau.norm());
            assert_eq!(f.wrench_torque(&tau), tau);
            let dq = f.solve(&tau);
            assert!((jr * dq - tau).norm() < 1e-12 * tau.norm() * dq.norm().max(1.0));
        }
    }

    #[test]
    fn near_a_singularity_the_solve_is_damped_by_the_documented_law() {
        let tau = JointVector::<4>::new(3.0, -2.0, 48.0, 0.5);
        let jr = jr([0.3, 1e-4, 0.2, 0.1]);
        let m = measure(&jr);
        assert!(m < SINGULARITY_THRESHOLD);
        let f = JacobianFactor::new(&jr);
        assert_eq!(f.how(), JacobianSolve::Damped);
        let lambda = MAX_DAMPING * (1.0 - m / SINGULARITY_THRESHOLD);
        let a = jr.transpose() * jr + JointMatrix::<4>::identity() * (lambda * lambda);
        let a_inv = a.try_inverse().unwrap();
        let expected = jr * a_inv * tau;
        let w = f.transpose_solve(&tau);
        assert!((w - expected).norm() < 1e-9 * expected.norm());
        let expected_dq = a_inv * jr.transpose() * tau;
        assert!((f.solve(&tau) - expected_dq).norm() < 1e-9 * expected_dq.norm());
        let expected_torque = jr.transpose() * expected;
        assert!((f.wrench_torque(&tau) - expected_torque).norm() < 1e-9 * tau.norm());
        // At the singularity itself, full damping; a NaN gives zero, damped.
        assert_eq!(
            JacobianFactor::new(&self::jr([0.3, 0.0, 0.2, 0.1])).how(),
            JacobianSolve::Damped
        );
        let mut bad = jr;
        bad[(1, 1)] = f64::NAN;
        let f = JacobianFactor::new(&bad);
        assert_eq!(f.how(), JacobianSolve::Damped);
        assert_eq!(f.transpose_solve(&tau), JointVector::<4>::zeros());
        assert_eq!(f.solve(&tau), JointVector::<4>::zeros());
    }

    /// Normwise backward error of both exact solves at random SCARA states (the closed form
    /// has no pivoting, so its accuracy is checked where it is used, near the threshold too;
    /// measured 7.2e-15, about 32 machine epsilons).
    #[test]
    fn the_closed_form_solves_are_backward_stable_over_the_workspace() {
        use rand::rngs::Xoshiro256PlusPlus;
        use rand::{RngExt, SeedableRng};
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(0x4A_2026);
        let (lo, hi) = (Scara.lower_limits(), Scara.upper_limits());
        let (mut exact, mut worst) = (0, 0.0f64);
        for k in 0..10_000 {
            let mut q = JointVector::<4>::from_fn(|i, _| rng.random_range(lo[i]..=hi[i]));
            if k % 10 == 0 {
                // Near the stretched-out singularity, around the damping threshold.
                q[1] = rng.random_range(-0.02..=0.02);
            }
            let jr = jr(q.into());
            let b = JointVector::<4>::from_fn(|_, _| rng.random_range(-1.0..=1.0));
            let f = JacobianFactor::new(&jr);
            if f.how() != JacobianSolve::Exact {
                continue;
            }
            exact += 1;
            let x = f.solve(&b);
            let y = f.transpose_solve(&b);
            let backward =
                |r: JointVector<4>, x: JointVector<4>| r.norm() / (jr.norm() * x.norm() + b.norm());
            worst = worst
                .max(backward(jr * x - b, x))
                .max(backward(jr.transpose() * y - b, y));
        }
        println!("{exact} exact solves, largest normwise backward error {worst:e}");
        assert!(exact > 9_500, "{exact} exact solves");
        assert!(worst < 5e-14, "backward error {worst:e}");
    }

    #[test]
    fn six_joints_go_through_the_lu_factors() {
        use crate::model::Puma560;
        let tau = nalgebra::SVector::<f64, 6>::new(3.0, -2.0, 48.0, 0.5, 1.0, -0.3);
        let q = nalgebra::SVector::<f64, 6>::new(0.1, -0.4, 0.3, 0.2, -0.5, 0.7);
        let j = Puma560.jacobian(&q);
        let f = JacobianFactor::from_rows(&j, &[0, 1, 2, 3, 4, 5]);
        assert_eq!(f.how(), JacobianSolve::Exact);
        assert!(matches!(f.factor, Factor::Exact(_)));
        assert_relative_eq!(
            j.transpose() * f.transpose_solve(&tau),
            tau,
            epsilon = 1e-11
        );
        assert_relative_eq!(j * f.solve(&tau), tau, epsilon = 1e-11);
        // The wrist singularity (q5 = 0): damped.
        let mut q0 = q;
        q0[4] = 0.0;
        let f = JacobianFactor::from_rows(&Puma560.jacobian(&q0), &[0, 1, 2, 3, 4, 5]);
        assert_eq!(f.how(), JacobianSolve::Damped);
    }

    #[test]
    fn the_damping_floor_is_the_scalar_s_own_smallest_normal() {
        assert_eq!(min_positive::<f64>(), f64::MIN_POSITIVE);
        assert_eq!(min_positive::<f32>(), f32::MIN_POSITIVE);
    }

    #[test]
    fn a_zero_row_is_damped_not_divided_by() {
        let mut jr = jr([0.3, 0.8, 0.2, 0.1]);
        jr.set_row(3, &nalgebra::RowVector4::zeros());
        let f = JacobianFactor::new(&jr);
        assert_eq!(f.how(), JacobianSolve::Damped);
        let w = f.transpose_solve(&JointVector::<4>::new(1.0, 2.0, 3.0, 4.0));
        assert!(w.iter().all(|x| x.is_finite()));
    }
}
