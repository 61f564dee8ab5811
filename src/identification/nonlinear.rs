//! Nonlinear least squares `min_x |r(x)|^2` by Levenberg-Marquardt (MINPACK's trust-region
//! variant, from the `levenberg-marquardt` crate).
//!
//! The crate is built on nalgebra 0.34 while the project is on 0.35: the residual and its
//! Jacobian are computed in the project's types and copied into the crate's at this one
//! boundary.

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra::{DMatrix, DVector};
use nalgebra_lm as lm;

/// When a run stops: on its evaluation budget, or converged on the relative change of the cost
/// or of the step (MINPACK's tests, on the whole cost `|r|^2 / 2`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stopping {
    /// Residual evaluations allowed: the run never spends more.
    pub max_evaluations: usize,
    /// Converged when a step changed the cost by at most this fraction of it, both as the
    /// linearised model predicted and actually (`ftol`).
    pub cost_tolerance: f64,
    /// Converged when the trust region (the longest step allowed) is at most this fraction of
    /// the scaled parameters' norm (`xtol`).
    pub step_tolerance: f64,
    /// Converged (stationary) when the cosine between the residual and every Jacobian column
    /// is at most this (`gtol`).
    pub gradient_tolerance: f64,
}

impl Stopping {
    /// `max_evaluations` residual evaluations, every tolerance `1e-12` (a small problem run
    /// to rounding).
    #[must_use]
    pub fn tight(max_evaluations: usize) -> Self {
        Self {
            max_evaluations,
            cost_tolerance: 1e-12,
            step_tolerance: 1e-12,
            gradient_tolerance: 1e-12,
        }
    }
}

/// Why a run stopped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Termination {
    /// A convergence test passed: the cost's relative change (`cost`), the step's (`step`).
    Converged {
        /// The cost test passed.
        cost: bool,
        /// The step test passed.
        step: bool,
    },
    /// The residual is orthogonal to the Jacobian's columns (a stationary point) or zero.
    Stationary,
    /// The budget of residual evaluations is spent.
    BudgetExhausted,
    /// The solver could not go on: a tolerance below rounding, a non-finite value, a model
    /// undefined at the start (the solver's own words).
    Failed(String),
}

impl Termination {
    /// The step test alone ended the run.
    pub const STEP_CONVERGED: Self = Self::Converged {
        cost: false,
        step: true,
    };
    /// The cost test alone ended the run.
    pub const COST_CONVERGED: Self = Self::Converged {
        cost: true,
        step: false,
    };

    /// Whether a convergence test ended the run.
    #[must_use]
    pub fn converged(&self) -> bool {
        matches!(self, Self::Converged { .. } | Self::Stationary)
    }
}

impl Termination {
    /// What stopped the run: `the relative change of the cost`, `the budget`, ...
    #[must_use]
    pub fn rule(&self) -> String {
        match self {
            Self::Converged { cost, step } => match (cost, step) {
                (true, true) => "the relative change of the cost and of the step".into(),
                (true, false) => "the relative change of the cost".into(),
                _ => "the relative change of the step".into(),
            },
            Self::Stationary => "a stationary point".into(),
            Self::BudgetExhausted => "the budget".into(),
            Self::Failed(why) => why.clone(),
        }
    }
}

impl core::fmt::Display for Termination {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Converged { cost, step } => {
                let on = match (cost, step) {
                    (true, true) => "the relative change of the cost and of the step",
                    (true, false) => "the relative change of the cost",
                    _ => "the relative change of the step",
                };
                write!(f, "converged on {on}")
            }
            Self::Stationary => write!(f, "converged: a stationary point"),
            Self::BudgetExhausted => write!(f, "budget exhausted"),
            Self::Failed(why) => write!(f, "stopped: {why}"),
        }
    }
}

/// What a nonlinear least-squares run ended with.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// The minimiser (the point of least cost evaluated).
    pub x: DVector<f64>,
    /// `|r(x)|^2 / 2` at the minimiser.
    pub cost: f64,
    /// Cost at the start.
    pub initial_cost: f64,
    /// Residual evaluations spent (at most the budget).
    pub evaluations: usize,
    /// Derivative evaluations: Jacobians (Levenberg-Marquardt: the first and one per
    /// accepted step), or gradients and Hessians (one per Newton step of the barrier solver).
    pub derivatives: usize,
    /// The budget of residual evaluations.
    pub budget: usize,
    /// Why it stopped.
    pub termination: Termination,
    /// Whether a convergence test stopped it ([`Termination::converged`]).
    pub converged: bool,
}

struct Problem<'a, F> {
    x: lm::DVector<f64>,
    model: F,
    /// Residual evaluations, and the budget.
    evaluations: usize,
    budget: usize,
    derivatives: usize,
    /// The point of least cost evaluated, and its cost.
    best: Option<(f64, lm::DVector<f64>)>,
    /// Cost at the first evaluation (the start).
    initial_cost: f64,
    progress: Option<&'a mut dyn FnMut(usize, usize)>,
}

/// The parameters and the model behind a cell, so the trait's `&self` methods can call an
/// `FnMut`.
struct CellProblem<'a, F> {
    inner: core::cell::RefCell<Problem<'a, F>>,
}

impl<F> LeastSquaresProblem<f64, lm::Dyn, lm::Dyn> for CellProblem<'_, F>
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
        let mut guard = self.inner.borrow_mut();
        let p = &mut *guard;
        // The budget: a refused evaluation ends the run (as "the model is undefined"), which
        // `minimize` reports as the budget spent.
        if p.evaluations >= p.budget {
            return None;
        }
        p.evaluations += 1;
        if let Some(report) = p.progress.as_mut() {
            report(p.evaluations, p.budget);
        }
        let x = DVector::from_column_slice(p.x.as_slice());
        let (r, _) = (p.model)(&x, false)?;
        if !r.iter().all(|v| v.is_finite()) {
            return None;
        }
        let cost = 0.5 * r.norm_squared();
        if p.evaluations == 1 {
            p.initial_cost = cost;
        }
        if p.best.as_ref().is_none_or(|(c, _)| cost < *c) {
            p.best = Some((cost, p.x.clone()));
        }
        Some(lm::DVector::from_column_slice(r.as_slice()))
    }

    fn jacobian(&self) -> Option<lm::DMatrix<f64>> {
        let mut p = self.inner.borrow_mut();
        p.derivatives += 1;
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
/// defined (the solver then shortens its step). At most `stopping.max_evaluations` residual
/// evaluations.
pub fn minimize<F>(x0: &DVector<f64>, stopping: &Stopping, model: F) -> Solution
where
    F: FnMut(&DVector<f64>, bool) -> Option<(DVector<f64>, Option<DMatrix<f64>>)>,
{
    minimize_reporting(x0, stopping, model, None)
}

/// [`minimize`], calling `progress(evaluations, budget)` at every residual evaluation.
pub fn minimize_reporting<F>(
    x0: &DVector<f64>,
    stopping: &Stopping,
    model: F,
    progress: Option<&mut dyn FnMut(usize, usize)>,
) -> Solution
where
    F: FnMut(&DVector<f64>, bool) -> Option<(DVector<f64>, Option<DMatrix<f64>>)>,
{
    let budget = stopping.max_evaluations.max(1);
    let problem = CellProblem {
        inner: core::cell::RefCell::new(Problem {
            x: lm::DVector::from_column_slice(x0.as_slice()),
            model,
            evaluations: 0,
            budget,
            derivatives: 0,
            best: None,
            initial_cost: f64::NAN,
            progress,
        }),
    };
    // The crate's own limit is `patience (n + 1)` evaluations: set at or above the budget,
    // which the problem enforces exactly.
    let patience = budget.div_ceil(x0.len() + 1).max(1);
    let solver = LevenbergMarquardt::new()
        .with_patience(patience)
        .with_ftol(stopping.cost_tolerance)
        .with_xtol(stopping.step_tolerance)
        .with_gtol(stopping.gradient_tolerance);
    let (problem, report) = solver.minimize(problem);
    let p = problem.inner.into_inner();
    let spent = p.evaluations >= budget;
    let termination = match report.termination {
        TerminationReason::Converged { ftol, xtol } => Termination::Converged {
            cost: ftol,
            step: xtol,
        },
        TerminationReason::Orthogonal | TerminationReason::ResidualsZero => Termination::Stationary,
        TerminationReason::LostPatience => Termination::BudgetExhausted,
        TerminationReason::User(_) if spent => Termination::BudgetExhausted,
        other => Termination::Failed(format!("{other:?}")),
    };
    let (cost, x) = match p.best {
        Some((c, x)) => (c, DVector::from_column_slice(x.as_slice())),
        None => (f64::NAN, x0.clone()),
    };
    Solution {
        x,
        cost,
        initial_cost: p.initial_cost,
        evaluations: p.evaluations,
        derivatives: p.derivatives,
        budget,
        converged: termination.converged(),
        termination,
    }
}
