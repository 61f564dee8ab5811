//! The log-Cholesky parametrisation of a link's inertial parameters (Rucker and Wensing,
//! "Smooth parameterization of rigid-body inertia", RA-L 2022): the ten standard parameters
//! `(m, m c, I_O)` (mass kg, first moment kg m, inertia about the link frame's origin kg m^2)
//! are those of a rigid body exactly when the pseudo-inertia
//!
//! ```text
//! J = [ Sigma  h ]     Sigma = tr(I_O)/2 1 - I_O  (the second moment of the mass),  h = m c
//!     [ h^T    m ]
//! ```
//!
//! is positive definite (mass > 0 and the triangle inequalities of the inertia at the centre of
//! mass follow). `J = U U^T` with `U = e^a [[e^d1, s12, s13, t1], [0, e^d2, s23, t2],
//! [0, 0, e^d3, t3], [0, 0, 0, 1]]` covers every positive definite `J` once, with ten free
//! numbers `theta = (a, d1, d2, d3, s12, s23, s13, t1, t2, t3)`; [`standard_of_theta`] gives
//! the parameters and their derivatives in closed form. [`fit_log_cholesky`]: the consistent
//! fit by Levenberg-Marquardt in those numbers.

use nalgebra::{DMatrix, DVector, Matrix4, SymmetricEigen};

use super::error::IdentificationError;
use super::estimation::Compressed;
use super::nonlinear::{minimize_reporting, Solution, Stopping};
use super::robots::PER_LINK;

/// Smallest eigenvalue of a pseudo-inertia made consistent, relative to its largest.
pub const EIGEN_FLOOR: f64 = 1e-4;

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

/// `U(theta)`, with `e^a` and `(e^d1, e^d2, e^d3)`.
fn unit_factor(theta: &[f64]) -> (Matrix4<f64>, f64, [f64; 3]) {
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
    (unit * s, s, e)
}

/// A link's standard parameters at `theta` (without the derivatives: one residual
/// evaluation's work).
#[must_use]
pub fn standard_at(theta: &[f64]) -> [f64; PER_LINK] {
    let (u, _, _) = unit_factor(theta);
    standard_of(&(u * u.transpose()))
}

/// `U(theta)`, and its derivative along each of the ten parameters.
fn factor(theta: &[f64]) -> (Matrix4<f64>, [Matrix4<f64>; PER_LINK]) {
    let (u, s, e) = unit_factor(theta);
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

/// The consistent fit by Levenberg-Marquardt in the log-Cholesky numbers of every link (the
/// extra parameters as they are): `J_l = U U^T + MARGIN J_0,l` (`floor[l]` the standard
/// parameters of `MARGIN J_0,l`), from `J_0,l (1 - MARGIN)` (`start`: the consistent prior) and
/// `extra0`. The residual is `[R x - z ; d (pi - prior) ; sqrt(rest)]`, its Jacobian in closed
/// form ([`standard_of_theta`], block by block). The solution's `x` is the parameters.
///
/// # Errors
///
/// [`IdentificationError::Estimation`] if a prior pseudo-inertia is not positive definite.
#[allow(clippy::too_many_arguments)]
pub fn fit_log_cholesky(
    data: &Compressed,
    prior: &DVector<f64>,
    d: &[f64],
    floor: &[[f64; PER_LINK]],
    start: &[f64],
    extra0: &DVector<f64>,
    stop: &Stopping,
    progress: Option<&mut dyn FnMut(usize, usize)>,
) -> Result<Solution, IdentificationError> {
    let (r, z) = (&data.r, &data.z);
    let links = prior.len() / PER_LINK;
    let p = links * PER_LINK;
    let nx = p + extra0.len();
    let mut x0 = DVector::zeros(nx);
    for l in 0..links {
        let j0 = pseudo_inertia(&start[l * PER_LINK..(l + 1) * PER_LINK]);
        let theta = theta_of(&(j0 - pseudo_inertia(&floor[l])))?;
        x0.rows_mut(l * PER_LINK, PER_LINK).copy_from_slice(&theta);
    }
    x0.rows_mut(p, extra0.len()).copy_from(extra0);
    // `x(v)`: the standard parameters of every link's numbers, the extra ones as they are.
    let map = |v: &DVector<f64>| {
        let mut x = v.clone();
        for l in 0..links {
            let pl = standard_at(&v.as_slice()[l * PER_LINK..(l + 1) * PER_LINK]);
            for k in 0..PER_LINK {
                x[l * PER_LINK + k] = pl[k] + floor[l][k];
            }
        }
        x
    };
    let rest = libm::sqrt(data.rest);
    let rows = z.len() + p + 1;
    let model = |v: &DVector<f64>, with_jacobian: bool| {
        let x = map(v);
        let mut res = DVector::zeros(rows);
        res.rows_mut(0, z.len()).copy_from(&(r * &x - z));
        for k in 0..p {
            res[z.len() + k] = d[k] * (x[k] - prior[k]);
        }
        res[rows - 1] = rest;
        let jac = with_jacobian.then(|| {
            // Block by block: `R dx / dv` with `dx / dv` block diagonal (10 x 10 per link,
            // the identity for the extra parameters); the last row (the rest) is constant.
            let mut j = DMatrix::zeros(rows, nx);
            for l in 0..links {
                let (_, jl) = standard_of_theta(&v.as_slice()[l * PER_LINK..(l + 1) * PER_LINK]);
                let cols = r.columns(l * PER_LINK, PER_LINK);
                j.view_mut((0, l * PER_LINK), (z.len(), PER_LINK))
                    .copy_from(&(cols * &jl));
                for k in 0..PER_LINK {
                    let row = jl.row(k) * d[l * PER_LINK + k];
                    j.view_mut((z.len() + l * PER_LINK + k, l * PER_LINK), (1, PER_LINK))
                        .copy_from(&row);
                }
            }
            j.view_mut((0, p), (z.len(), nx - p))
                .copy_from(&r.columns(p, nx - p));
            j
        });
        Some((res, jac))
    };
    let mut solution = minimize_reporting(&x0, stop, model, progress);
    solution.x = map(&solution.x);
    Ok(solution)
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
}
