//! Physically consistent standard parameters: a least-squares fit over parameters a real body
//! can have, by the log-Cholesky parametrisation of each link's pseudo-inertia (Rucker and
//! Wensing, "Smooth parameterization of rigid-body inertia", RA-L 2022) and Levenberg-Marquardt
//! ([`super::nonlinear`]).
//!
//! A link's ten standard parameters `(m, m c, I_O)` (mass kg, first moment kg m, inertia about
//! the link frame's origin kg m^2) are those of a rigid body exactly when its pseudo-inertia
//!
//! ```text
//! J = [ Sigma  h ]     Sigma = tr(I_O)/2 1 - I_O  (the second moment of the mass),  h = m c
//!     [ h^T    m ]
//! ```
//!
//! is positive definite (mass > 0 and the triangle inequalities of the inertia at the centre of
//! mass follow). `J = U U^T` with `U = e^a [[e^d1, s12, s13, t1], [0, e^d2, s23, t2],
//! [0, 0, e^d3, t3], [0, 0, 0, 1]]` covers every positive definite `J` once, with ten free
//! numbers `theta = (a, d1, d2, d3, s12, s23, s13, t1, t2, t3)`: the fit is unconstrained in
//! `theta` and consistent by construction ([`MARGIN`] keeps it off the boundary).
//!
//! The data fix only the base combinations of the standard parameters; among the equivalent
//! standard sets a prior chooses: the residual is
//! `[R x - z ; sqrt(PRIOR_WEIGHT) (pi - pi_0) / s]`, with `R x - z` the weighted data residual
//! compressed by QR (`|W x - y| = |R x - z|` up to a constant), `pi_0` the description's
//! parameters (made consistent first where they are not) and `s` per-parameter scales
//! ([`prior_scales`]).

use nalgebra::{DMatrix, DVector, Matrix4, SymmetricEigen};

use super::error::IdentificationError;
use super::nonlinear::{minimize, Solution};
use super::robots::PER_LINK;

/// Weight of the prior, in units of the weighted data residual (unit variance per row): small
/// enough that it moves the identifiable combinations by a negligible part of their
/// uncertainty, large enough to fix the unidentifiable ones.
pub const PRIOR_WEIGHT: f64 = 1e-3;
/// Smallest eigenvalue of a pseudo-inertia made consistent, relative to its largest.
pub const EIGEN_FLOOR: f64 = 1e-4;
/// Margin of consistency: every link's fitted pseudo-inertia is `U U^T + MARGIN J_0` with
/// `J_0` the (consistent) prior's, so its smallest eigenvalue is at least `MARGIN` times the
/// prior's: a body strictly inside the physical set, not on its boundary (a fit the data push
/// to the boundary, such as a link whose true parameters break the triangle inequality, stays
/// a body the generator accepts).
pub const MARGIN: f64 = 1e-6;
/// Residual evaluations allowed to the solver.
pub const MAX_EVALUATIONS: usize = 4000;

/// The pseudo-inertia `J` of one link's ten standard parameters.
#[must_use]
pub fn pseudo_inertia(p: &[f64]) -> Matrix4<f64> {
    let (m, h) = (p[0], [p[1], p[2], p[3]]);
    let i = nalgebra::Matrix3::new(p[4], p[5], p[6], p[5], p[7], p[8], p[6], p[8], p[9]);
    let sigma = nalgebra::Matrix3::identity() * (0.5 * i.trace()) - i;
    let mut j = Matrix4::zeros();
    j.fixed_view_mut::<3, 3>(0, 0).copy_from(&sigma);
    for r in 0..3 {
        j[(r, 3)] = h[r];
        j[(3, r)] = h[r];
    }
    j[(3, 3)] = m;
    j
}

/// The ten standard parameters of a pseudo-inertia (the inverse of [`pseudo_inertia`], linear).
#[must_use]
pub fn standard_of(j: &Matrix4<f64>) -> [f64; PER_LINK] {
    let sigma = j.fixed_view::<3, 3>(0, 0);
    let t = sigma.trace();
    let i = |r: usize, c: usize| {
        if r == c {
            t - sigma[(r, c)]
        } else {
            -sigma[(r, c)]
        }
    };
    [
        j[(3, 3)],
        j[(0, 3)],
        j[(1, 3)],
        j[(2, 3)],
        i(0, 0),
        i(0, 1),
        i(0, 2),
        i(1, 1),
        i(1, 2),
        i(2, 2),
    ]
}

/// Smallest eigenvalue of a link's pseudo-inertia (> 0: the parameters are a rigid body's).
#[must_use]
pub fn smallest_eigenvalue(p: &[f64]) -> f64 {
    SymmetricEigen::new(pseudo_inertia(p)).eigenvalues.min()
}

/// `U(theta)`, and its derivative along each of the ten parameters.
fn factor(theta: &[f64]) -> (Matrix4<f64>, [Matrix4<f64>; PER_LINK]) {
    let s = libm::exp(theta[0]);
    let e = [
        libm::exp(theta[1]),
        libm::exp(theta[2]),
        libm::exp(theta[3]),
    ];
    #[rustfmt::skip]
    let unit = Matrix4::new(
        e[0], theta[4], theta[6], theta[7],
        0.0,  e[1],     theta[5], theta[8],
        0.0,  0.0,      e[2],     theta[9],
        0.0,  0.0,      0.0,      1.0,
    );
    let u = unit * s;
    let mut d = [Matrix4::zeros(); PER_LINK];
    d[0] = u;
    for k in 0..3 {
        d[1 + k][(k, k)] = s * e[k];
    }
    let entries = [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)];
    for (k, (r, c)) in entries.iter().enumerate() {
        d[4 + k][(*r, *c)] = s;
    }
    (u, d)
}

/// A link's standard parameters at `theta`, and `d pi / d theta` (10 x 10).
#[must_use]
pub fn standard_of_theta(theta: &[f64]) -> ([f64; PER_LINK], DMatrix<f64>) {
    let (u, du) = factor(theta);
    let p = standard_of(&(u * u.transpose()));
    let mut jac = DMatrix::zeros(PER_LINK, PER_LINK);
    for (k, d) in du.iter().enumerate() {
        let dj = d * u.transpose() + u * d.transpose();
        let dp = standard_of(&dj);
        for r in 0..PER_LINK {
            jac[(r, k)] = dp[r];
        }
    }
    (p, jac)
}

/// `theta` of a positive definite pseudo-inertia: `J = U U^T` with `U` upper triangular is the
/// Cholesky factor of `J` with rows and columns reversed.
///
/// # Errors
///
/// [`IdentificationError::Estimation`] if `J` is not positive definite.
pub fn theta_of(j: &Matrix4<f64>) -> Result<[f64; PER_LINK], IdentificationError> {
    let rev = Matrix4::from_fn(|r, c| j[(3 - r, 3 - c)]);
    let l = rev.cholesky().ok_or_else(|| {
        IdentificationError::Estimation("a pseudo-inertia is not positive definite".into())
    })?;
    let l = l.l();
    let u = Matrix4::from_fn(|r, c| l[(3 - r, 3 - c)]);
    let s = u[(3, 3)];
    let v = u / s;
    Ok([
        libm::log(s),
        libm::log(v[(0, 0)]),
        libm::log(v[(1, 1)]),
        libm::log(v[(2, 2)]),
        v[(0, 1)],
        v[(1, 2)],
        v[(0, 2)],
        v[(0, 3)],
        v[(1, 3)],
        v[(2, 3)],
    ])
}

/// The nearest consistent parameters of a link in the sense of the pseudo-inertia's spectrum:
/// eigenvalues below [`EIGEN_FLOOR`] times the largest raised to it (a massless or
/// non-physical link becomes a small consistent body).
#[must_use]
pub fn make_consistent(p: &[f64]) -> [f64; PER_LINK] {
    let eig = SymmetricEigen::new(pseudo_inertia(p));
    let largest = eig.eigenvalues.max().max(1e-9);
    let floor = EIGEN_FLOOR * largest;
    if eig.eigenvalues.min() >= floor {
        let mut out = [0.0; PER_LINK];
        out.copy_from_slice(&p[..PER_LINK]);
        return out;
    }
    let lambda = eig.eigenvalues.map(|l| l.max(floor));
    let j = eig.eigenvectors * Matrix4::from_diagonal(&lambda) * eig.eigenvectors.transpose();
    standard_of(&(0.5 * (j + j.transpose())))
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

/// A consistent fit.
#[derive(Clone, Debug, PartialEq)]
pub struct ConsistentFit {
    /// Standard parameters, every link's pseudo-inertia positive definite.
    pub standard: DVector<f64>,
    /// The extra (friction, offset) parameters fitted with them.
    pub extra: DVector<f64>,
    /// Smallest pseudo-inertia eigenvalue per link (all > 0).
    pub smallest_eigenvalues: Vec<f64>,
    /// The solver's report.
    pub solution: Solution,
}

/// Fits `x = [pi (10 links); extra]` to the compressed data `|R x - z|` with the prior
/// `prior` (the description's standard parameters), starting from the prior made consistent
/// and `extra0`.
///
/// # Errors
///
/// [`IdentificationError::Estimation`] for mismatched sizes or a result that is not finite.
pub fn fit_consistent(
    r: &DMatrix<f64>,
    z: &DVector<f64>,
    prior: &DVector<f64>,
    extra0: &DVector<f64>,
) -> Result<ConsistentFit, IdentificationError> {
    let links = prior.len() / PER_LINK;
    let p = links * PER_LINK;
    let nx = p + extra0.len();
    if !prior.len().is_multiple_of(PER_LINK) || r.ncols() != nx || r.nrows() != z.len() {
        return Err(IdentificationError::Estimation(format!(
            "consistent fit: {} x {} data for {} standard and {} extra parameters",
            r.nrows(),
            r.ncols(),
            prior.len(),
            extra0.len()
        )));
    }
    let scales = prior_scales(prior.as_slice());
    let start: Vec<f64> = (0..links)
        .flat_map(|l| make_consistent(&prior.as_slice()[l * PER_LINK..(l + 1) * PER_LINK]))
        .collect();
    let floor: Vec<[f64; PER_LINK]> = (0..links)
        .map(|l| {
            let j0 = pseudo_inertia(&start[l * PER_LINK..(l + 1) * PER_LINK]);
            standard_of(&(j0 * MARGIN))
        })
        .collect();
    let mut x0 = DVector::zeros(nx);
    for l in 0..links {
        let j0 = pseudo_inertia(&start[l * PER_LINK..(l + 1) * PER_LINK]);
        let theta = theta_of(&(j0 * (1.0 - MARGIN)))?;
        x0.rows_mut(l * PER_LINK, PER_LINK).copy_from_slice(&theta);
    }
    x0.rows_mut(p, extra0.len()).copy_from(extra0);
    let w = libm::sqrt(PRIOR_WEIGHT);
    let map = |v: &DVector<f64>| {
        let mut x = DVector::zeros(nx);
        let mut dx = DMatrix::zeros(nx, nx);
        for l in 0..links {
            let (pl, jl) = standard_of_theta(&v.as_slice()[l * PER_LINK..(l + 1) * PER_LINK]);
            for k in 0..PER_LINK {
                x[l * PER_LINK + k] = pl[k] + floor[l][k];
            }
            dx.view_mut((l * PER_LINK, l * PER_LINK), (PER_LINK, PER_LINK))
                .copy_from(&jl);
        }
        for k in p..nx {
            x[k] = v[k];
            dx[(k, k)] = 1.0;
        }
        (x, dx)
    };
    let solution = minimize(&x0, MAX_EVALUATIONS, |v, with_jacobian| {
        let (x, dx) = map(v);
        let mut res = DVector::zeros(z.len() + p);
        res.rows_mut(0, z.len()).copy_from(&(r * &x - z));
        for k in 0..p {
            res[z.len() + k] = w * (x[k] - prior[k]) / scales[k];
        }
        let jac = with_jacobian.then(|| {
            let mut j = DMatrix::zeros(z.len() + p, nx);
            j.view_mut((0, 0), (z.len(), nx)).copy_from(&(r * &dx));
            for (k, scale) in scales.iter().enumerate() {
                let row = dx.row(k) * (w / scale);
                j.row_mut(z.len() + k).copy_from(&row);
            }
            j
        });
        Some((res, jac))
    });
    let (x, _) = map(&solution.x);
    if x.iter().any(|v| !v.is_finite()) {
        return Err(IdentificationError::Estimation(format!(
            "consistent fit: the solver ended on a non-finite estimate ({})",
            solution.termination
        )));
    }
    let standard = x.rows(0, p).into_owned();
    let smallest_eigenvalues = (0..links)
        .map(|l| smallest_eigenvalue(&standard.as_slice()[l * PER_LINK..(l + 1) * PER_LINK]))
        .collect();
    Ok(ConsistentFit {
        standard,
        extra: x.rows(p, nx - p).into_owned(),
        smallest_eigenvalues,
        solution,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const LINK: [f64; PER_LINK] = [2.0, 0.1, -0.05, 0.2, 0.09, 0.002, -0.01, 0.1, 0.005, 0.05];

    #[test]
    fn parametrisation_round_trips_and_its_jacobian_is_right() {
        let theta = theta_of(&pseudo_inertia(&LINK)).unwrap();
        let (p, jac) = standard_of_theta(&theta);
        for k in 0..PER_LINK {
            approx::assert_relative_eq!(p[k], LINK[k], epsilon = 1e-12);
        }
        let h = 1e-6;
        for k in 0..PER_LINK {
            let (mut a, mut b) = (theta, theta);
            a[k] += h;
            b[k] -= h;
            let (pa, pb) = (standard_of_theta(&a).0, standard_of_theta(&b).0);
            for r in 0..PER_LINK {
                approx::assert_relative_eq!(
                    jac[(r, k)],
                    (pa[r] - pb[r]) / (2.0 * h),
                    epsilon = 1e-7
                );
            }
        }
    }

    #[test]
    fn inconsistent_parameters_are_detected_and_repaired() {
        // Izz larger than Ixx + Iyy at the centre of mass: no rigid body.
        let mut bad = LINK;
        bad[9] = 0.5;
        assert!(smallest_eigenvalue(&bad) < 0.0);
        assert!(theta_of(&pseudo_inertia(&bad)).is_err());
        let fixed = make_consistent(&bad);
        assert!(smallest_eigenvalue(&fixed) > 0.0);
        assert_eq!(make_consistent(&LINK), LINK);
    }

    #[test]
    fn an_inconsistent_least_squares_optimum_is_pulled_back_to_a_body() {
        // Data that pin every parameter to an inconsistent set: the fit stays consistent.
        let mut bad = LINK;
        bad[9] = 0.5;
        let r = DMatrix::identity(PER_LINK, PER_LINK) * 100.0;
        let z = DVector::from_column_slice(&bad) * 100.0;
        let fit = fit_consistent(
            &r,
            &z,
            &DVector::from_column_slice(&LINK),
            &DVector::zeros(0),
        )
        .unwrap();
        assert!(fit.smallest_eigenvalues[0] > 0.0);
        // Consistent data: the quadratic optimum of data and prior, per parameter
        // `(r^2 pi + w_k pi_0) / (r^2 + w_k)` with `w_k = PRIOR_WEIGHT / s_k^2`, recovered to
        // the solver's tolerance (with `r = 100` the prior's pull is visible; on a log `r` is
        // `sqrt(rows) / sigma`, thousands, and the pull negligible).
        let z = DVector::from_column_slice(&LINK) * 100.0;
        let prior = make_consistent(&[1.0, 0.0, 0.0, 0.0, 0.01, 0.0, 0.0, 0.01, 0.0, 0.01]);
        let fit = fit_consistent(
            &r,
            &z,
            &DVector::from_column_slice(&prior),
            &DVector::zeros(0),
        )
        .unwrap();
        let scales = prior_scales(&prior);
        for k in 0..PER_LINK {
            let wp = PRIOR_WEIGHT / (scales[k] * scales[k]);
            let expected = (1e4 * LINK[k] + wp * prior[k]) / (1e4 + wp);
            approx::assert_relative_eq!(fit.standard[k], expected, epsilon = 1e-8);
        }
    }
}
