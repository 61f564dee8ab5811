//! The consistent fit by an interior-point method: the problem in the standard parameters is
//! convex (a quadratic cost, every link's pseudo-inertia kept positive definite: linear matrix
//! inequalities), so a log-barrier path-following Newton method solves it to a certified
//! accuracy (Boyd and Vandenberghe, "Convex Optimization", ch. 11).
//!
//! For a barrier weight `mu` the method minimises
//! `phi(x) = f(x) - mu sum_l ln det S_l(x)` with `f` the least-squares cost and
//! `S_l = J(pi_l) - MARGIN J_0,l` (each link's pseudo-inertia less the margin), by Newton steps
//! (gradient and Hessian in closed form: `d/dx_k (-ln det S) = -tr(S^-1 E_k)`,
//! `d2/dx_k dx_j = tr(S^-1 E_k S^-1 E_j)` with `E_k = dJ/dpi_k` constant) with a backtracking
//! line search that keeps every `S_l` positive definite; then lowers `mu` tenfold. At the
//! minimiser of `phi`, `f` is within `4 L mu` (`L` links, 4 per 4 x 4 inequality) of the
//! constrained minimum: the run stops when that bound, plus the last Newton decrement, is at
//! most the cost tolerance times the cost (the relative change of the cost still possible),
//! or when a Newton step no longer moves the parameters (relative to their norm, the step
//! tolerance). Factorisations: nalgebra's Cholesky.

use nalgebra::{Cholesky, DMatrix, DVector, Matrix4};

use super::log_cholesky::pseudo_inertia;
use super::nonlinear::{Solution, Stopping, Termination};
use super::robots::PER_LINK;

/// Barrier weight divided by this between centerings.
const MU_FACTOR: f64 = 10.0;
/// Armijo fraction of the line search.
const ARMIJO: f64 = 0.25;
/// A centering stops when the Newton decrement `lambda^2 / 2` is at most this fraction of the
/// barrier's gap bound `4 L mu`.
const CENTERING: f64 = 0.01;
/// Newton steps per centering at most.
const NEWTON_PER_CENTERING: usize = 100;

/// The fit's problem: `f(x) = (|A x - b|^2 + rest) / 2` with each link's `S_l(x)` positive
/// definite.
pub struct BarrierProblem<'a> {
    /// The stacked data and prior rows.
    pub a: &'a DMatrix<f64>,
    /// Their right-hand side.
    pub b: &'a DVector<f64>,
    /// The data's part no parameter explains.
    pub rest: f64,
    /// Links: the first `10 L` parameters are theirs.
    pub links: usize,
    /// Per link, the standard parameters of `MARGIN J_0` (subtracted before the inequality).
    pub floor: &'a [[f64; PER_LINK]],
}

impl BarrierProblem<'_> {
    fn cost(&self, x: &DVector<f64>) -> f64 {
        0.5 * ((self.a * x - self.b).norm_squared() + self.rest)
    }

    /// `S_l(x)` of every link, `None` if one is not positive definite.
    fn slacks(&self, x: &DVector<f64>) -> Option<Vec<Cholesky<f64, nalgebra::U4>>> {
        (0..self.links)
            .map(|l| {
                let mut p = [0.0; PER_LINK];
                for (k, v) in p.iter_mut().enumerate() {
                    *v = x[l * PER_LINK + k] - self.floor[l][k];
                }
                pseudo_inertia(&p).cholesky()
            })
            .collect()
    }

    /// `phi(x)` for barrier weight `mu`, `None` outside the set.
    fn phi(&self, x: &DVector<f64>, mu: f64) -> Option<f64> {
        let s = self.slacks(x)?;
        let log_det: f64 = s
            .iter()
            .map(|c| {
                c.l()
                    .diagonal()
                    .iter()
                    .map(|d| 2.0 * libm::log(*d))
                    .sum::<f64>()
            })
            .sum();
        Some(self.cost(x) - mu * log_det)
    }
}

/// Minimises the problem from the strictly feasible `x0`, stopping by `stop` (its budget
/// counts evaluations of `phi`, its tolerances as in the module's description);
/// `progress(evaluations, budget)` after each Newton step. `initial_gap`: an estimate of
/// `f(x0) - f*` that sets the first barrier weight.
pub fn minimize_barrier(
    problem: &BarrierProblem<'_>,
    x0: &DVector<f64>,
    initial_gap: f64,
    stop: &Stopping,
    mut progress: Option<&mut dyn FnMut(usize, usize)>,
) -> Solution {
    let budget = stop.max_evaluations.max(1);
    let m = 4.0 * problem.links as f64;
    let e: Vec<Matrix4<f64>> = (0..PER_LINK)
        .map(|k| {
            let mut unit = [0.0; PER_LINK];
            unit[k] = 1.0;
            pseudo_inertia(&unit)
        })
        .collect();
    let h0 = problem.a.tr_mul(problem.a);
    let g0 = problem.a.tr_mul(problem.b);
    let mut x = x0.clone();
    let initial_cost = problem.cost(&x);
    let mut mu = (initial_gap.max(1e-12 * initial_cost) / m).max(f64::MIN_POSITIVE);
    let (mut evaluations, mut newton) = (1, 0);
    let finish = |x: DVector<f64>, evaluations, newton, termination: Termination| Solution {
        cost: problem.cost(&x),
        x,
        initial_cost,
        evaluations,
        derivatives: newton,
        budget,
        converged: termination.converged(),
        termination,
    };
    loop {
        let mut decrement = f64::INFINITY;
        for _ in 0..NEWTON_PER_CENTERING {
            let Some(slacks) = problem.slacks(&x) else {
                return finish(
                    x,
                    evaluations,
                    newton,
                    Termination::Failed("left the set".into()),
                );
            };
            let mut g = &h0 * &x - &g0;
            let mut h = h0.clone();
            for (l, s) in slacks.iter().enumerate() {
                let inv = s.inverse();
                let se: Vec<Matrix4<f64>> = e.iter().map(|ek| inv * ek).collect();
                for i in 0..PER_LINK {
                    g[l * PER_LINK + i] -= mu * se[i].trace();
                    for j in 0..PER_LINK {
                        h[(l * PER_LINK + i, l * PER_LINK + j)] += mu * (se[i] * se[j]).trace();
                    }
                }
            }
            let dx = match h.clone().cholesky() {
                Some(c) => c.solve(&(-&g)),
                None => match h.lu().solve(&(-&g)) {
                    Some(dx) => dx,
                    None => {
                        let why = "a singular Newton system".into();
                        return finish(x, evaluations, newton, Termination::Failed(why));
                    }
                },
            };
            newton += 1;
            decrement = -g.dot(&dx);
            if !decrement.is_finite() {
                let why = "a non-finite Newton step".into();
                return finish(x, evaluations, newton, Termination::Failed(why));
            }
            if 0.5 * decrement <= CENTERING * m * mu {
                break;
            }
            if dx.norm() <= stop.step_tolerance * x.norm() {
                return finish(x, evaluations, newton, Termination::STEP_CONVERGED);
            }
            // Backtracking: feasible, and Armijo's decrease.
            let phi0 = problem.phi(&x, mu).unwrap_or(f64::INFINITY);
            let mut t = 1.0;
            loop {
                if evaluations >= budget {
                    return finish(x, evaluations, newton, Termination::BudgetExhausted);
                }
                evaluations += 1;
                let trial = &x + &dx * t;
                if let Some(v) = problem.phi(&trial, mu) {
                    if v <= phi0 - ARMIJO * t * decrement {
                        x = trial;
                        break;
                    }
                }
                t *= 0.5;
                if t < 1e-12 {
                    // No decrease along a descent direction: rounding; the step is nil.
                    return finish(x, evaluations, newton, Termination::STEP_CONVERGED);
                }
            }
            if let Some(report) = progress.as_mut() {
                report(evaluations, budget);
            }
        }
        let cost = problem.cost(&x);
        if m * mu + 0.5 * decrement <= stop.cost_tolerance * cost {
            return finish(x, evaluations, newton, Termination::COST_CONVERGED);
        }
        mu /= MU_FACTOR;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_mass_pulled_outside_stops_on_the_boundary_with_its_gap_certified() {
        // One link, data pinning its parameters to a set with Izz larger than Ixx + Iyy at the
        // centre of mass (no rigid body): the minimum over the set is on its edge.
        let target = [2.0, 0.1, -0.05, 0.2, 0.09, 0.002, -0.01, 0.1, 0.005, 0.5];
        let a = DMatrix::identity(PER_LINK, PER_LINK) * 10.0;
        let b = DVector::from_column_slice(&target) * 10.0;
        let consistent = [2.0, 0.1, -0.05, 0.2, 0.09, 0.002, -0.01, 0.1, 0.005, 0.05];
        let floor = [[0.0; PER_LINK]];
        let problem = BarrierProblem {
            a: &a,
            b: &b,
            rest: 100.0,
            links: 1,
            floor: &floor,
        };
        let x0 = DVector::from_column_slice(&consistent);
        let stop = Stopping {
            max_evaluations: 4000,
            cost_tolerance: 1e-10,
            step_tolerance: 1e-12,
            gradient_tolerance: 0.0,
        };
        let s = minimize_barrier(&problem, &x0, problem.cost(&x0) - 50.0, &stop, None);
        assert_eq!(s.termination, Termination::COST_CONVERGED);
        assert!(s.evaluations < 400, "{}", s.evaluations);
        // On the edge: the pseudo-inertia nearly singular, still positive definite.
        let j = pseudo_inertia(s.x.as_slice());
        let eig = j.symmetric_eigenvalues();
        assert!(eig.min() > 0.0 && eig.min() < 1e-6 * eig.max(), "{eig}");
        // Certified: no consistent point of the segment to the target's projection does
        // better, and the cost is within the tolerance of the minimum along random feasible
        // directions.
        use rand::{RngExt, SeedableRng};
        let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(12345);
        for _ in 0..200 {
            let dir = DVector::from_fn(PER_LINK, |_, _| rng.random_range(-0.5..0.5));
            for t in [1e-4, 1e-3, 1e-2] {
                let y = &s.x + &dir * t;
                if pseudo_inertia(y.as_slice()).cholesky().is_some() {
                    assert!(problem.cost(&y) >= s.cost * (1.0 - 1e-9));
                }
            }
        }
    }
}
