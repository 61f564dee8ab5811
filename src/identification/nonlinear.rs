//! Nonlinear least squares `min_x |r(x)|^2` by Levenberg-Marquardt (MINPACK's trust-region
//! variant, from the `levenberg-marquardt` crate).
//!
//! The crate is built on nalgebra 0.34 while the project is on 0.35: the residual and its
//! Jacobian are computed in the project's types and copied into the crate's at this one
//! boundary.

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::{DMatrix, DVector};
use nalgebra_lm as lm;

/// What a nonlinear least-squares run ended with.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// The minimiser.
    pub x: DVector<f64>,
    /// `|r(x)|^2 / 2` at the minimiser.
    pub cost: f64,
    /// Residual evaluations spent.
    pub evaluations: usize,
    /// Whether the solver stopped on a convergence test (not on its evaluation budget or a
    /// numerical failure).
    pub converged: bool,
    /// The solver's reason for stopping, as text.
    pub termination: String,
}

struct Problem<F> {
    x: lm::DVector<f64>,
    model: F,
}

/// The parameters and the model behind a cell, so the trait's `&self` methods can call an
/// `FnMut`.
struct CellProblem<F> {
    inner: core::cell::RefCell<Problem<F>>,
}

impl<F> LeastSquaresProblem<f64, lm::Dyn, lm::Dyn> for CellProblem<F>
where
    F: FnMut(&DVector<f64>, bool) -> Option<(DVector<f64>, Option<DMatrix<f64>>)>,
{
    type ResidualStorage = lm::VecStorage<f64, lm::Dyn, lm::U1>;
    type JacobianStorage = lm::VecStorage<f64, lm::Dyn, lm::Dyn>;
    type ParameterStorage = lm::VecStorage<f64, lm::Dyn, lm::U1>;

    fn set_params(&mut self, x: &lm::DVector<f64>) {
        self.inner.get_mut().x.copy_from(x);
    }

    fn params(&self) -> lm::DVector<f64> {
        self.inner.borrow().x.clone()
    }

    fn residuals(&self) -> Option<lm::DVector<f64>> {
        let mut p = self.inner.borrow_mut();
        let x = DVector::from_column_slice(p.x.as_slice());
        let (r, _) = (p.model)(&x, false)?;
        r.iter()
            .all(|v| v.is_finite())
            .then(|| lm::DVector::from_column_slice(r.as_slice()))
    }

    fn jacobian(&self) -> Option<lm::DMatrix<f64>> {
        let mut p = self.inner.borrow_mut();
        let x = DVector::from_column_slice(p.x.as_slice());
        let (_, j) = (p.model)(&x, true)?;
        let j = j?;
        j.iter()
            .all(|v| v.is_finite())
            .then(|| lm::DMatrix::from_column_slice(j.nrows(), j.ncols(), j.as_slice()))
    }
}

/// Minimises `|r(x)|^2 / 2` from `x0`. `model(x, with_jacobian)` returns `r(x)` and, when asked,
/// its Jacobian `dr/dx` (rows: residuals, columns: parameters); `None` where the model is not
/// defined (the solver then shortens its step). At most `max_evaluations` residual evaluations.
pub fn minimize<F>(x0: &DVector<f64>, max_evaluations: usize, model: F) -> Solution
where
    F: FnMut(&DVector<f64>, bool) -> Option<(DVector<f64>, Option<DMatrix<f64>>)>,
{
    let problem = CellProblem {
        inner: core::cell::RefCell::new(Problem {
            x: lm::DVector::from_column_slice(x0.as_slice()),
            model,
        }),
    };
    let solver = LevenbergMarquardt::new()
        .with_patience(max_evaluations.max(1))
        .with_ftol(1e-12)
        .with_xtol(1e-12)
        .with_gtol(1e-12);
    let (problem, report) = solver.minimize(problem);
    let x = DVector::from_column_slice(problem.inner.borrow().x.as_slice());
    Solution {
        x,
        cost: report.objective_function,
        evaluations: report.number_of_evaluations,
        converged: report.termination.was_successful(),
        termination: format!("{:?}", report.termination),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_an_exponential() {
        // r_k = a exp(b t_k) - y_k with y from a = 2, b = -0.7.
        let t: Vec<f64> = (0..20).map(|k| f64::from(k) * 0.2).collect();
        let y: Vec<f64> = t.iter().map(|t| 2.0 * libm::exp(-0.7 * t)).collect();
        let s = minimize(&DVector::from_vec(vec![1.0, 0.0]), 200, |x, jac| {
            let r = DVector::from_fn(t.len(), |k, _| x[0] * libm::exp(x[1] * t[k]) - y[k]);
            let j = jac.then(|| {
                DMatrix::from_fn(t.len(), 2, |k, c| {
                    let e = libm::exp(x[1] * t[k]);
                    if c == 0 {
                        e
                    } else {
                        x[0] * t[k] * e
                    }
                })
            });
            Some((r, j))
        });
        assert!(s.converged, "{}", s.termination);
        approx::assert_relative_eq!(s.x[0], 2.0, epsilon = 1e-9);
        approx::assert_relative_eq!(s.x[1], -0.7, epsilon = 1e-9);
    }
}
