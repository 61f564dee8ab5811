//! Physically consistent standard parameters: the least-squares fit over parameters a real
//! body can have.
//!
//! The data fix only the base combinations of the standard parameters; among the equivalent
//! standard sets a prior chooses: the cost is
//! `f(x) = (|R x - z|^2 + |d (pi - pi_0)|^2 + rest) / 2`, with `R x - z` the weighted data
//! residual compressed by QR and `rest` the part of it no parameter can explain
//! ([`Compressed`]: `|W x - y|^2 = |R x - z|^2 + rest`, so `f` is the whole weighted
//! least-squares cost), `pi_0` the description's parameters (made consistent first where they
//! are not) and `d = sqrt(PRIOR_WEIGHT) / s` with per-parameter scales `s` ([`prior_scales`]).
//! `x = [pi; extra]`, the extra parameters (friction, offsets) unconstrained. Every link's
//! pseudo-inertia must stay positive definite, with a margin: `J(pi_l) - MARGIN J_0,l`
//! positive definite ([`MARGIN`]).
//!
//! That problem is convex (a quadratic cost over linear matrix inequalities). Two solvers
//! ([`ConsistentSolver`]):
//!
//! - [`ConsistentSolver::Barrier`] (the default): an interior-point method
//!   ([`super::barrier`]), which stops when the cost is certified within a relative `1e-10`
//!   of the constrained minimum.
//! - [`ConsistentSolver::LogCholesky`]: Levenberg-Marquardt in the log-Cholesky numbers of each
//!   link ([`super::log_cholesky`], closed-form Jacobian), unconstrained in those numbers.
//!   Where the data push a link to the boundary of the set those numbers run off to infinity
//!   and the steps gain less and less: the run stops on the relative change of the cost or of
//!   the step, short of the constrained minimum.
//!
//! Since the problem is convex, its constrained minimum is on the boundary of the set exactly
//! when the unconstrained minimum of the same cost is outside it. [`fit_consistent`] computes
//! that unconstrained minimum too (a linear least squares), names the links it puts outside
//! (the data push them to the boundary) and the ratio of the two costs.

use nalgebra::{DMatrix, DVector};

use super::barrier::{minimize_barrier, BarrierProblem};
use super::error::IdentificationError;
pub use super::estimation::Compressed;
pub use super::log_cholesky::{
    fit_log_cholesky, make_consistent, pseudo_inertia, smallest_eigenvalue, standard_at,
    standard_of, standard_of_theta, theta_of, EIGEN_FLOOR,
};
use super::nonlinear::{Solution, Stopping, Termination};
use super::robots::PER_LINK;

/// Weight of the prior, in units of the weighted data residual (unit variance per row): small
/// enough that it moves the identifiable combinations by a negligible part of their
/// uncertainty, large enough to fix the unidentifiable ones.
pub const PRIOR_WEIGHT: f64 = 1e-3;
/// Margin of consistency: every link's fitted pseudo-inertia is at least `MARGIN J_0` with
/// `J_0` the (consistent) prior's, so its smallest eigenvalue is at least `MARGIN` times the
/// prior's: a body strictly inside the physical set, not on its boundary (a fit the data push
/// to the boundary, such as a link whose true parameters break the triangle inequality, stays
/// a body the generator accepts).
pub const MARGIN: f64 = 1e-6;
/// Evaluations of the cost allowed to either solver (the budget; Jacobians, gradients and
/// Hessians are counted apart).
pub const MAX_EVALUATIONS: usize = 4000;
/// The barrier solver stops when the cost is within this fraction of the constrained minimum
/// (its certified bound: the barrier's gap plus the last Newton decrement). The rows are
/// weighted to unit variance and a log has thousands: the cost is thousands, and `1e-10` of it
/// is far below what the noise resolves (a change of 0.5 is one standard deviation along one
/// direction).
pub const BARRIER_COST_TOLERANCE: f64 = 1e-10;
/// The barrier solver also stops when a Newton step moves the parameters by at most this
/// fraction of their norm (rounding).
pub const BARRIER_STEP_TOLERANCE: f64 = 1e-12;
/// The log-Cholesky solver stops when a step changes the cost by at most this fraction of it,
/// both as predicted and actually: about `1e-4` in units of one row's variance on a log of
/// thousands of rows. Where the data push a link to the consistency boundary the log-Cholesky
/// numbers run off to infinity and every step gains less: this is what stops that crawl.
pub const COST_TOLERANCE: f64 = 1e-8;
/// The log-Cholesky solver also stops when the trust region (the longest step allowed) is at
/// most this fraction of the scaled parameters' norm.
pub const STEP_TOLERANCE: f64 = 1e-8;

/// The method of the consistent fit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ConsistentSolver {
    /// Interior point: log barrier, Newton steps ([`super::barrier`]).
    #[default]
    Barrier,
    /// Levenberg-Marquardt in the log-Cholesky numbers ([`fit_log_cholesky`]).
    LogCholesky,
}

impl ConsistentSolver {
    /// `barrier` or `log-cholesky`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Barrier => "barrier",
            Self::LogCholesky => "log-cholesky",
        }
    }

    /// The stopping rule of this solver: [`MAX_EVALUATIONS`] and its tolerances.
    #[must_use]
    pub fn stopping(self) -> Stopping {
        let (cost, step) = match self {
            Self::Barrier => (BARRIER_COST_TOLERANCE, BARRIER_STEP_TOLERANCE),
            Self::LogCholesky => (COST_TOLERANCE, STEP_TOLERANCE),
        };
        Stopping {
            max_evaluations: MAX_EVALUATIONS,
            cost_tolerance: cost,
            step_tolerance: step,
            gradient_tolerance: 0.0,
        }
    }
}

/// Scales of the prior per standard parameter: the description's value where it is not small,
/// else a floor per kind (mass 0.1 kg, first moment 0.01 kg m, inertia 0.001 kg m^2).
#[must_use]
pub fn prior_scales(prior: &[f64]) -> Vec<f64> {
    prior
        .iter()
        .enumerate()
        .map(|(k, v)| {
            let floor = match k % PER_LINK {
                0 => 0.1,
                1..=3 => 0.01,
                _ => 0.001,
            };
            v.abs().max(floor)
        })
        .collect()
}

/// How the fit ended.
#[derive(Clone, Debug, PartialEq)]
pub enum FitStatus {
    /// Converged inside the physically consistent set: the unconstrained minimum is consistent
    /// too, and the two fits are the same.
    Converged,
    /// Converged at the consistency boundary: the unconstrained minimum puts these links (from
    /// 1) outside the physical set, the constrained one stops at its edge.
    AtBoundary(Vec<usize>),
    /// The solver spent its budget of evaluations before a convergence test passed.
    BudgetExhausted,
    /// The solver stopped without converging (its words).
    Failed(String),
}

impl FitStatus {
    /// Whether the solver converged ([`Self::Converged`] or [`Self::AtBoundary`]).
    #[must_use]
    pub fn converged(&self) -> bool {
        matches!(self, Self::Converged | Self::AtBoundary(_))
    }

    /// `converged`, `at the consistency boundary`, `budget exhausted` or `failed`.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Converged => "converged",
            Self::AtBoundary(_) => "at the consistency boundary",
            Self::BudgetExhausted => "budget exhausted",
            Self::Failed(_) => "failed",
        }
    }
}

impl core::fmt::Display for FitStatus {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::AtBoundary(links) => {
                let names: Vec<String> = links.iter().map(ToString::to_string).collect();
                write!(
                    f,
                    "converged at the consistency boundary (link{} {})",
                    if links.len() == 1 { "" } else { "s" },
                    names.join(", ")
                )
            }
            Self::Failed(why) => write!(f, "failed ({why})"),
            other => f.write_str(other.name()),
        }
    }
}

/// The minimum of the same cost without the consistency constraint (a linear least squares).
#[derive(Clone, Debug, PartialEq)]
pub struct Unconstrained {
    /// Standard parameters.
    pub standard: DVector<f64>,
    /// Extra parameters.
    pub extra: DVector<f64>,
    /// The cost `|r|^2 / 2` at it.
    pub cost: f64,
    /// Links (from 1) it puts outside the consistent set, with their smallest pseudo-inertia
    /// eigenvalue there.
    pub outside: Vec<(usize, f64)>,
}

/// A consistent fit.
#[derive(Clone, Debug, PartialEq)]
pub struct ConsistentFit {
    /// Standard parameters, every link's pseudo-inertia positive definite.
    pub standard: DVector<f64>,
    /// The extra (friction, offset) parameters fitted with them.
    pub extra: DVector<f64>,
    /// Smallest pseudo-inertia eigenvalue per link (all > 0).
    pub smallest_eigenvalues: Vec<f64>,
    /// The solver used.
    pub solver: ConsistentSolver,
    /// The solver's report (`x`: the parameters, standard then extra).
    pub solution: Solution,
    /// How it ended.
    pub status: FitStatus,
    /// The unconstrained minimum of the same cost.
    pub unconstrained: Unconstrained,
    /// The constrained cost over the unconstrained one (>= 1 to rounding): how far the
    /// consistent fit is from the best fit without the constraint.
    pub cost_ratio: f64,
}

/// The prior's rows: `sqrt(PRIOR_WEIGHT) / s_k` per standard parameter.
fn prior_rows(scales: &[f64]) -> Vec<f64> {
    let w = libm::sqrt(PRIOR_WEIGHT);
    scales.iter().map(|s| w / s).collect()
}

/// The data and prior rows stacked: `f(x) = (|A x - b|^2 + rest) / 2`.
fn stacked(data: &Compressed, prior: &DVector<f64>, d: &[f64]) -> (DMatrix<f64>, DVector<f64>) {
    let (nx, p) = (data.r.ncols(), prior.len());
    let mut a = DMatrix::zeros(data.r.nrows() + p, nx);
    let mut b = DVector::zeros(data.r.nrows() + p);
    a.view_mut((0, 0), data.r.shape()).copy_from(&data.r);
    b.rows_mut(0, data.z.len()).copy_from(&data.z);
    for k in 0..p {
        a[(data.r.nrows() + k, k)] = d[k];
        b[data.r.nrows() + k] = d[k] * prior[k];
    }
    (a, b)
}

/// The minimum of `f` over `x`, without the constraint.
fn unconstrained(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
    rest: f64,
    p: usize,
    floor: &[[f64; PER_LINK]],
) -> Result<Unconstrained, IdentificationError> {
    let nx = a.ncols();
    let qr = a.clone().qr();
    let mut qtb = b.clone();
    qr.q_tr_mul(&mut qtb);
    let x = qr
        .r()
        .solve_upper_triangular(&qtb.rows(0, nx).into_owned())
        .ok_or_else(|| {
            IdentificationError::Estimation(
                "consistent fit: the unconstrained comparison is singular".into(),
            )
        })?;
    let cost = 0.5 * ((a * &x - b).norm_squared() + rest);
    let outside = (0..p / PER_LINK)
        .filter_map(|l| {
            let link = &x.as_slice()[l * PER_LINK..(l + 1) * PER_LINK];
            // Outside when `J - MARGIN J_0` is not positive definite.
            let shifted: Vec<f64> = link.iter().zip(&floor[l]).map(|(v, f)| v - f).collect();
            (smallest_eigenvalue(&shifted) <= 0.0).then(|| (l + 1, smallest_eigenvalue(link)))
        })
        .collect();
    Ok(Unconstrained {
        standard: x.rows(0, p).into_owned(),
        extra: x.rows(p, nx - p).into_owned(),
        cost,
        outside,
    })
}

/// Fits `x = [pi (10 links); extra]` to the compressed data with the prior `prior` (the
/// description's standard parameters) by `solver`, starting from the prior made consistent
/// and `extra0`, stopping by `stop` (`solver.stopping()` on a log); `progress(evaluations,
/// budget)` as it goes.
///
/// # Errors
///
/// [`IdentificationError::Estimation`] for mismatched sizes or a result that is not finite.
pub fn fit_consistent(
    data: &Compressed,
    prior: &DVector<f64>,
    extra0: &DVector<f64>,
    solver: ConsistentSolver,
    stop: &Stopping,
    progress: Option<&mut dyn FnMut(usize, usize)>,
) -> Result<ConsistentFit, IdentificationError> {
    let links = prior.len() / PER_LINK;
    let p = links * PER_LINK;
    let nx = p + extra0.len();
    if !prior.len().is_multiple_of(PER_LINK)
        || data.r.ncols() != nx
        || data.r.nrows() != data.z.len()
    {
        return Err(IdentificationError::Estimation(format!(
            "consistent fit: {} x {} data for {} standard and {} extra parameters",
            data.r.nrows(),
            data.r.ncols(),
            prior.len(),
            extra0.len()
        )));
    }
    let d = prior_rows(&prior_scales(prior.as_slice()));
    let start: Vec<f64> = (0..links)
        .flat_map(|l| make_consistent(&prior.as_slice()[l * PER_LINK..(l + 1) * PER_LINK]))
        .collect();
    let floor: Vec<[f64; PER_LINK]> = (0..links)
        .map(|l| {
            let j0 = pseudo_inertia(&start[l * PER_LINK..(l + 1) * PER_LINK]);
            standard_of(&(j0 * MARGIN))
        })
        .collect();
    let (a, b) = stacked(data, prior, &d);
    let unconstrained = unconstrained(&a, &b, data.rest, p, &floor)?;
    let solution = match solver {
        ConsistentSolver::Barrier => {
            let mut x0 = DVector::zeros(nx);
            x0.rows_mut(0, p).copy_from_slice(&start);
            x0.rows_mut(p, extra0.len()).copy_from(extra0);
            let problem = BarrierProblem {
                a: &a,
                b: &b,
                rest: data.rest,
                links,
                floor: &floor,
            };
            let gap = 0.5 * ((&a * &x0 - &b).norm_squared() + data.rest) - unconstrained.cost;
            minimize_barrier(&problem, &x0, gap, stop, progress)
        }
        ConsistentSolver::LogCholesky => {
            fit_log_cholesky(data, prior, &d, &floor, &start, extra0, stop, progress)?
        }
    };
    let x = &solution.x;
    if x.iter().any(|v| !v.is_finite()) {
        return Err(IdentificationError::Estimation(format!(
            "consistent fit: the solver ended on a non-finite estimate ({})",
            solution.termination
        )));
    }
    let status = match &solution.termination {
        Termination::BudgetExhausted => FitStatus::BudgetExhausted,
        Termination::Failed(why) => FitStatus::Failed(why.clone()),
        _ if unconstrained.outside.is_empty() => FitStatus::Converged,
        _ => FitStatus::AtBoundary(unconstrained.outside.iter().map(|(l, _)| *l).collect()),
    };
    let standard = x.rows(0, p).into_owned();
    let smallest_eigenvalues = (0..links)
        .map(|l| smallest_eigenvalue(&standard.as_slice()[l * PER_LINK..(l + 1) * PER_LINK]))
        .collect();
    Ok(ConsistentFit {
        standard,
        extra: x.rows(p, nx - p).into_owned(),
        smallest_eigenvalues,
        cost_ratio: solution.cost / unconstrained.cost,
        solver,
        solution,
        status,
        unconstrained,
    })
}
