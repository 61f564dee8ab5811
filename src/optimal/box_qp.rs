//! A small quadratic programme with bounds, the step of control-limited iLQR:
//!
//! ```text
//! minimise  1/2 x^T H x + g^T x   subject to   lo <= x <= hi        (H symmetric)
//! ```
//!
//! solved by projected Newton (Bertsekas 1982, as used for control-limited DDP by Tassa,
//! Mansard and Todorov 2014): at each iterate the variables at a bound whose gradient pushes
//! outward are clamped, a Newton step is taken in the others (Cholesky of their block of
//! `H`), projected onto the box, and shortened by backtracking until the objective
//! decreases. The result says which variables are free: iLQR's feedback acts only on those.
//!
//! Written here rather than taken from a solver crate because it runs once per knot of
//! every backward pass on a few variables (the joints), must return the free set and the
//! factor of its block, and must not allocate more than a few small matrices: the QP
//! crates in Rust solve general sparse problems through a setup that costs more than this
//! whole solve.

use nalgebra::{Cholesky, DMatrix, DVector, Dyn};

/// Iteration cap of [`solve`].
pub const MAX_ITERATIONS: usize = 100;

/// The solution of a box QP.
#[derive(Clone, Debug)]
pub struct BoxQpSolution {
    /// The minimiser.
    pub x: DVector<f64>,
    /// Whether each variable is free (not held at a bound) at the solution.
    pub free: Vec<bool>,
    /// Cholesky factor of `H` restricted to the free variables (`None` if none is free).
    pub free_factor: Option<Cholesky<f64, Dyn>>,
}

/// Why a box QP could not be solved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum BoxQpError {
    /// `H` restricted to the free variables is not positive definite.
    #[error("the QP's Hessian is not positive definite on its free variables")]
    NotPositiveDefinite,
}

/// `1/2 x^T H x + g^T x`.
fn objective(h: &DMatrix<f64>, g: &DVector<f64>, x: &DVector<f64>) -> f64 {
    0.5 * x.dot(&(h * x)) + g.dot(x)
}

/// `x` clamped into `[lo, hi]`.
fn project(x: &DVector<f64>, lo: &DVector<f64>, hi: &DVector<f64>) -> DVector<f64> {
    DVector::from_fn(x.len(), |i, _| x[i].clamp(lo[i], hi[i]))
}

/// Indices of the free variables at `x` (not at a bound with the gradient pushing out).
fn free_set(
    x: &DVector<f64>,
    grad: &DVector<f64>,
    lo: &DVector<f64>,
    hi: &DVector<f64>,
) -> Vec<bool> {
    (0..x.len())
        .map(|i| !((x[i] <= lo[i] && grad[i] > 0.0) || (x[i] >= hi[i] && grad[i] < 0.0)))
        .collect()
}

/// `H` restricted to the rows and columns where `free`, factorised.
fn factor_free(h: &DMatrix<f64>, free: &[bool]) -> Result<Option<Cholesky<f64, Dyn>>, BoxQpError> {
    let idx: Vec<usize> = (0..free.len()).filter(|&i| free[i]).collect();
    if idx.is_empty() {
        return Ok(None);
    }
    let sub = DMatrix::from_fn(idx.len(), idx.len(), |r, c| h[(idx[r], idx[c])]);
    sub.cholesky()
        .map(Some)
        .ok_or(BoxQpError::NotPositiveDefinite)
}

/// Solves the box QP from the start `x0` (projected into the box first); `lo <= hi`
/// elementwise (infinite bounds allowed).
///
/// # Errors
///
/// [`BoxQpError::NotPositiveDefinite`] if a Newton step meets a block of `H` that is not
/// positive definite.
pub fn solve(
    h: &DMatrix<f64>,
    g: &DVector<f64>,
    lo: &DVector<f64>,
    hi: &DVector<f64>,
    x0: &DVector<f64>,
) -> Result<BoxQpSolution, BoxQpError> {
    let n = g.len();
    let mut x = project(x0, lo, hi);
    let mut value = objective(h, g, &x);
    for _ in 0..MAX_ITERATIONS {
        let grad = g + h * &x;
        let free = free_set(&x, &grad, lo, hi);
        let Some(factor) = factor_free(h, &free)? else {
            break;
        };
        let idx: Vec<usize> = (0..n).filter(|&i| free[i]).collect();
        let grad_free = DVector::from_fn(idx.len(), |r, _| grad[idx[r]]);
        if grad_free.amax() <= 1e-13 * (1.0 + g.amax()) {
            break;
        }
        let step_free = factor.solve(&grad_free);
        let mut direction = DVector::zeros(n);
        for (r, &i) in idx.iter().enumerate() {
            direction[i] = -step_free[r];
        }
        let mut step = 1.0;
        let mut accepted = false;
        while step > 1e-12 {
            let candidate = project(&(&x + &direction * step), lo, hi);
            let v = objective(h, g, &candidate);
            // Armijo on the projected arc (Bertsekas): sufficient decrease along the move.
            if v <= value + 1e-8 * grad.dot(&(&candidate - &x)) {
                let moved = (&candidate - &x).amax();
                x = candidate;
                let improvement = value - v;
                value = v;
                accepted = true;
                if moved <= 1e-15 * (1.0 + x.amax()) || improvement <= 1e-16 * (1.0 + value.abs()) {
                    step = 0.0; // converged: stop after recording
                }
                break;
            }
            step *= 0.5;
        }
        if !accepted || step == 0.0 {
            break;
        }
    }
    let grad = g + h * &x;
    let free = free_set(&x, &grad, lo, hi);
    let free_factor = factor_free(h, &free)?;
    Ok(BoxQpSolution {
        x,
        free,
        free_factor,
    })
}
