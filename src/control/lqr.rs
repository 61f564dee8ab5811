//! Linear-quadratic regulator design (std only): the continuous algebraic Riccati equation
//! `A^T P + P A - P B R^-1 B^T P + Q = 0` solved by the matrix sign function of the
//! Hamiltonian, then `K = R^-1 B^T P`.
//!
//! Design-time code: it allocates (dynamic matrices). The controller built from the gain
//! ([`FullStateFeedback`](super::fsf::FullStateFeedback)) does not.

use nalgebra::DMatrix;

/// Errors of the Riccati solve.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LqrError {
    /// Shapes of `A`, `B`, `Q`, `R` do not fit.
    #[error("LQR shapes do not fit: {0}")]
    Shape(&'static str),
    /// `R` is not invertible, or the Hamiltonian iteration met a singular matrix.
    #[error("singular matrix in the LQR design: {0}")]
    Singular(&'static str),
    /// The sign iteration did not converge (the pair is not stabilizable, or `Q` does not
    /// make it detectable).
    #[error("the Riccati solve did not converge in {0} iterations")]
    NoConvergence(usize),
}

/// The stabilizing solution `P` of the continuous algebraic Riccati equation, its gain
/// `K = R^-1 B^T P` and the relative residual
/// `|A^T P + P A - P B R^-1 B^T P + Q|_F / max(1, |Q|_F)`.
#[derive(Clone, Debug)]
pub struct LqrSolution {
    /// Riccati solution, symmetric positive semi-definite.
    pub p: DMatrix<f64>,
    /// Optimal gain, `u = -K x`.
    pub k: DMatrix<f64>,
    /// Relative residual of the Riccati equation.
    pub residual: f64,
}

/// Solves the LQR problem for `x' = A x + B u`, cost `int x^T Q x + u^T R u dt`.
///
/// # Errors
///
/// [`LqrError`] for mismatched shapes, a singular `R`, or no convergence.
///
/// ```
/// use nalgebra::DMatrix;
/// use armdyn::control::lqr::lqr;
/// // Double integrator, Q = I, R = 1: K = [1, sqrt(3)].
/// let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 0.0]);
/// let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
/// let s = lqr(&a, &b, &DMatrix::identity(2, 2), &DMatrix::identity(1, 1)).unwrap();
/// assert!((s.k[(0, 0)] - 1.0).abs() < 1e-10 && (s.k[(0, 1)] - 3f64.sqrt()).abs() < 1e-10);
/// assert!(s.residual < 1e-12);
/// ```
pub fn lqr(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    q: &DMatrix<f64>,
    r: &DMatrix<f64>,
) -> Result<LqrSolution, LqrError> {
    let n = a.nrows();
    if a.ncols() != n
        || b.nrows() != n
        || q.shape() != (n, n)
        || r.shape() != (b.ncols(), b.ncols())
    {
        return Err(LqrError::Shape("A n x n, B n x m, Q n x n, R m x m"));
    }
    let r_inv = r.clone().try_inverse().ok_or(LqrError::Singular("R"))?;
    let g = b * &r_inv * b.transpose();
    let mut h = DMatrix::<f64>::zeros(2 * n, 2 * n);
    h.view_mut((0, 0), (n, n)).copy_from(a);
    h.view_mut((0, n), (n, n)).copy_from(&(-&g));
    h.view_mut((n, 0), (n, n)).copy_from(&(-q));
    h.view_mut((n, n), (n, n)).copy_from(&(-a.transpose()));
    // Newton iteration for sign(H) with determinant scaling.
    const MAX_ITER: usize = 100;
    let mut z = h;
    let mut converged = false;
    for _ in 0..MAX_ITER {
        let det = z.clone().lu().determinant().abs();
        let c = if det.is_finite() && det > 0.0 {
            det.powf(-1.0 / (2.0 * n as f64))
        } else {
            1.0
        };
        let zc = &z * c;
        let inv = zc
            .clone()
            .try_inverse()
            .ok_or(LqrError::Singular("Hamiltonian iterate"))?;
        let next = (zc + inv) * 0.5;
        let change = (&next - &z).norm() / next.norm().max(1.0);
        z = next;
        if change < 1e-14 {
            converged = true;
            break;
        }
    }
    if !converged {
        return Err(LqrError::NoConvergence(MAX_ITER));
    }
    let eye = DMatrix::<f64>::identity(n, n);
    let w11 = z.view((0, 0), (n, n)).into_owned();
    let w12 = z.view((0, n), (n, n)).into_owned();
    let w21 = z.view((n, 0), (n, n)).into_owned();
    let w22 = z.view((n, n), (n, n)).into_owned();
    // [W12; W22 + I] P = -[W11 + I; W21], least squares.
    let mut lhs = DMatrix::<f64>::zeros(2 * n, n);
    lhs.view_mut((0, 0), (n, n)).copy_from(&w12);
    lhs.view_mut((n, 0), (n, n)).copy_from(&(w22 + &eye));
    let mut rhs = DMatrix::<f64>::zeros(2 * n, n);
    rhs.view_mut((0, 0), (n, n)).copy_from(&(-(w11 + &eye)));
    rhs.view_mut((n, 0), (n, n)).copy_from(&(-w21));
    let p = lhs
        .svd(true, true)
        .solve(&rhs, 1e-14)
        .map_err(|_| LqrError::Singular("stable subspace"))?;
    let p = (&p + p.transpose()) * 0.5;
    let residual = riccati_residual(a, b, q, &r_inv, &p);
    let k = &r_inv * b.transpose() * &p;
    Ok(LqrSolution { p, k, residual })
}

/// `|A^T P + P A - P B R^-1 B^T P + Q|_F / max(1, |Q|_F)`.
#[must_use]
pub fn riccati_residual(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    q: &DMatrix<f64>,
    r_inv: &DMatrix<f64>,
    p: &DMatrix<f64>,
) -> f64 {
    let res = a.transpose() * p + p * a - p * b * r_inv * b.transpose() * p + q;
    res.norm() / q.norm().max(1.0)
}
