//! Least-squares estimation of the base parameters from a measurement, ordinary and weighted
//! (Gautier's weighting: each joint's rows divided by the standard deviation of its ordinary
//! residual), with the estimate's relative standard deviations; least-squares data compressed
//! to one row per unknown ([`Compressed`]).

use nalgebra::{DMatrix, DVector};

use super::base::BaseParameters;
use super::error::IdentificationError;
use super::measurement::Measurement;
use super::robots::Identifiable;
use super::signals::full_regressor;
use crate::model::JointVector;

/// The stacked base regressor and torque vector of a measurement, rows ordered sample by
/// sample, joint by joint.
#[must_use]
pub fn stack<const N: usize, R: Identifiable<N>>(
    robot: &R,
    base: &BaseParameters,
    m: &Measurement<N>,
    friction_smoothing: Option<f64>,
    torques: &[JointVector<N>],
) -> (DMatrix<f64>, DVector<f64>) {
    let rows = m.q.len() * N;
    let mut w = DMatrix::zeros(rows, base.count());
    let mut y = DVector::zeros(rows);
    for k in 0..m.q.len() {
        let full = full_regressor(robot, &m.q[k], &m.qd[k], &m.qdd[k], friction_smoothing);
        w.view_mut((k * N, 0), (N, base.count()))
            .copy_from(&base.select(&full));
        for i in 0..N {
            y[k * N + i] = torques[k][i];
        }
    }
    (w, y)
}

/// Least squares `min |w x - y|` by QR: `R x = z` of the [`Compressed`] data.
///
/// # Errors
///
/// [`IdentificationError::Estimation`] with fewer rows than columns, mismatched sizes or a
/// singular `R`.
pub fn least_squares(
    w: &DMatrix<f64>,
    y: &DVector<f64>,
) -> Result<DVector<f64>, IdentificationError> {
    if w.nrows() < w.ncols() {
        return Err(IdentificationError::Estimation(format!(
            "{} equations for {} unknowns",
            w.nrows(),
            w.ncols()
        )));
    }
    let c = Compressed::of(w, y)?;
    c.r.solve_upper_triangular(&c.z).ok_or_else(|| {
        IdentificationError::Estimation("the base regressor is rank deficient".into())
    })
}

/// Weighted data `|W x - y|^2` compressed: `|R x - z|^2 + rest` with `W = Q R` (QR), `z` the
/// first `cols(W)` entries of `Q^T y` and `rest` the squared norm of the others (what lies
/// outside the columns of `W`).
#[derive(Clone, Debug, PartialEq)]
pub struct Compressed {
    /// Upper triangular, one row per parameter.
    pub r: DMatrix<f64>,
    /// `Q^T y`.
    pub z: DVector<f64>,
    /// `|y|^2 - |z|^2` (>= 0).
    pub rest: f64,
}

impl Compressed {
    /// Compresses `(w, y)` (at least as many rows as columns).
    ///
    /// # Errors
    ///
    /// [`IdentificationError::Estimation`] with fewer rows than columns or mismatched sizes.
    pub fn of(w: &DMatrix<f64>, y: &DVector<f64>) -> Result<Self, IdentificationError> {
        if w.nrows() < w.ncols() || w.nrows() != y.len() {
            return Err(IdentificationError::Estimation(format!(
                "compressed least squares: {} x {} data for {} torques",
                w.nrows(),
                w.ncols(),
                y.len()
            )));
        }
        let qr = w.clone().qr();
        // `Q^T y` by the Householder reflections (`Q` square): its first rows are `z`, the
        // others what no column explains.
        let mut qty = y.clone();
        qr.q_tr_mul(&mut qty);
        let z = qty.rows(0, w.ncols()).into_owned();
        let rest = qty.rows(w.ncols(), w.nrows() - w.ncols()).norm_squared();
        Ok(Self { r: qr.r(), z, rest })
    }

    /// `|R x - z|^2 + rest` (= `|W x - y|^2`).
    #[must_use]
    pub fn squared_norm(&self, x: &DVector<f64>) -> f64 {
        (&self.r * x - &self.z).norm_squared() + self.rest
    }
}

/// An estimate and how sure it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Ordinary least squares.
    pub ordinary: DVector<f64>,
    /// Weighted least squares.
    pub weighted: DVector<f64>,
    /// Standard deviation of each joint's ordinary residual (the weights' inverse), N m or N.
    pub residual_std: Vec<f64>,
    /// Relative standard deviation of each weighted estimate, % (`100 sigma_i / |x_i|`).
    pub relative_std_pct: Vec<f64>,
}

/// Ordinary and weighted least squares on the stacked `(w, y)` of an `n`-joint measurement.
///
/// # Errors
///
/// As [`least_squares`].
pub fn estimate(
    w: &DMatrix<f64>,
    y: &DVector<f64>,
    n: usize,
) -> Result<Estimate, IdentificationError> {
    let ordinary = least_squares(w, y)?;
    let residual = y - w * &ordinary;
    let samples = w.nrows() / n;
    let dof = (samples as f64 - w.ncols() as f64 / n as f64).max(1.0);
    let residual_std: Vec<f64> = (0..n)
        .map(|i| {
            let ss: f64 = (0..samples).map(|k| residual[k * n + i].powi(2)).sum();
            libm::sqrt(ss / dof)
        })
        .collect();
    let sigma = joint_sigmas(&residual_std);
    let (ww, yw) = weigh(w, y, &sigma);
    let weighted = least_squares(&ww, &yw)?;
    let rw = &yw - &ww * &weighted;
    let s2 = rw.norm_squared() / (ww.nrows() as f64 - ww.ncols() as f64).max(1.0);
    let relative_std_pct = match (ww.transpose() * &ww).try_inverse() {
        Some(c) => (0..weighted.len())
            .map(|j| 100.0 * libm::sqrt((s2 * c[(j, j)]).max(0.0)) / weighted[j].abs())
            .collect(),
        None => vec![f64::NAN; weighted.len()],
    };
    Ok(Estimate {
        ordinary,
        weighted,
        residual_std,
        relative_std_pct,
    })
}

/// Relative RMS error per joint of `predicted` against `reference`, % of the reference's RMS.
#[must_use]
pub fn rms_error_pct(predicted: &DVector<f64>, reference: &DVector<f64>, n: usize) -> Vec<f64> {
    let samples = reference.len() / n;
    (0..n)
        .map(|i| {
            let (mut e, mut r) = (0.0, 0.0);
            for k in 0..samples {
                e += (predicted[k * n + i] - reference[k * n + i]).powi(2);
                r += reference[k * n + i].powi(2);
            }
            100.0 * libm::sqrt(e / r)
        })
        .collect()
}

/// Per-joint weights from residual standard deviations: a joint with no residual at all
/// (noise-free data) gets the smallest non-zero one (or 1 when all are zero).
pub(crate) fn joint_sigmas(std: &[f64]) -> Vec<f64> {
    let floor = std
        .iter()
        .copied()
        .filter(|s| *s > 0.0)
        .fold(f64::INFINITY, f64::min);
    std.iter()
        .map(|s| {
            if *s > 0.0 {
                *s
            } else if floor.is_finite() {
                floor
            } else {
                1.0
            }
        })
        .collect()
}

/// The stacked regression `w p = y` (rows joint-major per sample, `sigma.len()` joints)
/// with each row divided by its joint's `sigma_i`.
pub(crate) fn weigh(
    w: &DMatrix<f64>,
    y: &DVector<f64>,
    sigma: &[f64],
) -> (DMatrix<f64>, DVector<f64>) {
    let n = sigma.len();
    let (mut w, mut y) = (w.clone(), y.clone());
    for r in 0..y.len() {
        let s = sigma[r % n];
        w.row_mut(r).scale_mut(1.0 / s);
        y[r] /= s;
    }
    (w, y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compression_keeps_the_whole_cost() {
        let w = DMatrix::from_fn(30, 3, |i, j| libm::sin((i * 3 + j) as f64));
        let y = DVector::from_fn(30, |i, _| libm::cos(i as f64));
        let c = Compressed::of(&w, &y).unwrap();
        let x = DVector::from_vec(vec![0.3, -1.0, 2.0]);
        approx::assert_relative_eq!(
            c.squared_norm(&x),
            (&w * &x - &y).norm_squared(),
            epsilon = 1e-12
        );
        assert!(Compressed::of(&w.transpose(), &y).is_err());
    }
}
