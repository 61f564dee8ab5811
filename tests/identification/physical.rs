//! Tests of `armdyn::identification::physical`: the physically consistent fit: an inconsistent
//! least-squares optimum pulled back to a body, and a spent budget reported.

use armdyn::identification::nonlinear::Stopping;
use armdyn::identification::physical::*;
use armdyn::model::PARAMETERS_PER_LINK as PER_LINK;
use nalgebra::{DMatrix, DVector};

const LINK: [f64; PER_LINK] = [2.0, 0.1, -0.05, 0.2, 0.09, 0.002, -0.01, 0.1, 0.005, 0.05];
const SOLVERS: [ConsistentSolver; 2] = [ConsistentSolver::Barrier, ConsistentSolver::LogCholesky];

/// Data `100 pi = 100 target` on every parameter, and a rest of `rest`.
fn pinned(target: &[f64; PER_LINK], rest: f64) -> Compressed {
    Compressed {
        r: DMatrix::identity(PER_LINK, PER_LINK) * 100.0,
        z: DVector::from_column_slice(target) * 100.0,
        rest,
    }
}

fn fit(data: &Compressed, prior: &[f64], solver: ConsistentSolver) -> ConsistentFit {
    let prior = DVector::from_column_slice(prior);
    let none = DVector::zeros(0);
    fit_consistent(data, &prior, &none, solver, &solver.stopping(), None).unwrap()
}

#[test]
fn an_inconsistent_least_squares_optimum_is_pulled_back_to_a_body() {
    // Data that pin every parameter to an inconsistent set: the fit stays consistent,
    // converges at the boundary and says so, its cost above the unconstrained one's.
    let mut bad = LINK;
    bad[9] = 0.5;
    let wp = PRIOR_WEIGHT / (LINK[9] * LINK[9]);
    let unconstrained_izz = (1e4 * 0.5 + wp * LINK[9]) / (1e4 + wp);
    let mut costs = Vec::new();
    for solver in SOLVERS {
        let fit = fit(&pinned(&bad, 1e4), &LINK, solver);
        assert!(fit.smallest_eigenvalues[0] > 0.0);
        assert_eq!(
            fit.status,
            FitStatus::AtBoundary(vec![1]),
            "{solver:?}: {}",
            fit.solution.termination
        );
        assert!(fit.solution.evaluations < MAX_EVALUATIONS);
        assert_eq!(fit.unconstrained.outside.len(), 1);
        assert!(fit.unconstrained.outside[0].1 < 0.0);
        assert!(fit.cost_ratio > 1.0, "{}", fit.cost_ratio);
        // The unconstrained minimum is that of data and prior, as below.
        approx::assert_relative_eq!(
            fit.unconstrained.standard[9],
            unconstrained_izz,
            epsilon = 1e-9
        );
        costs.push(fit.solution.cost);
    }
    // The barrier's certified minimum is at least as low as the crawl's.
    assert!(costs[0] <= costs[1] * (1.0 + 1e-9), "{costs:?}");
    // Consistent data: the quadratic optimum of data and prior, per parameter
    // `(r^2 pi + w_k pi_0) / (r^2 + w_k)` with `w_k = PRIOR_WEIGHT / s_k^2` (with `r = 100`
    // the prior's pull is visible; on a log `r` is `sqrt(rows) / sigma`, thousands, and
    // the pull negligible).
    let prior = make_consistent(&[1.0, 0.0, 0.0, 0.0, 0.01, 0.0, 0.0, 0.01, 0.0, 0.01]);
    for solver in SOLVERS {
        let fit = fit(&pinned(&LINK, 1e4), &prior, solver);
        assert_eq!(
            fit.status,
            FitStatus::Converged,
            "{}",
            fit.solution.termination
        );
        let scales = prior_scales(&prior);
        for k in 0..PER_LINK {
            let wp = PRIOR_WEIGHT / (scales[k] * scales[k]);
            let expected = (1e4 * LINK[k] + wp * prior[k]) / (1e4 + wp);
            approx::assert_relative_eq!(fit.standard[k], expected, epsilon = 1e-6);
            approx::assert_relative_eq!(fit.unconstrained.standard[k], expected, epsilon = 1e-9);
        }
        approx::assert_relative_eq!(fit.cost_ratio, 1.0, epsilon = 1e-9);
    }
}

#[test]
fn a_spent_budget_is_reported_as_such() {
    let mut bad = LINK;
    bad[9] = 0.5;
    for solver in SOLVERS {
        let stop = Stopping {
            max_evaluations: 3,
            ..solver.stopping()
        };
        let fit = fit_consistent(
            &pinned(&bad, 0.0),
            &DVector::from_column_slice(&LINK),
            &DVector::zeros(0),
            solver,
            &stop,
            None,
        )
        .unwrap();
        assert_eq!(fit.status, FitStatus::BudgetExhausted, "{solver:?}");
        assert!(!fit.status.converged());
        assert_eq!(fit.solution.evaluations, 3);
        assert!(fit.smallest_eigenvalues[0] > 0.0);
    }
}
