//! The smooth-Coulomb slopes of an identification from a log, by variable projection: for
//! slopes `v` (one per joint) the model `tau = Y pi + fv qd + fc tanh(qd / v) + fo` is linear
//! in everything else, so the slopes minimise the weighted residual with the rest solved by
//! least squares (Levenberg-Marquardt on `u = ln v`, forward-difference Jacobian, from the
//! best point of [`SLOPE_GRID`]).
//!
//! Only the Coulomb columns depend on the slopes. The other base columns `A` (the rigid
//! body's, the viscous and offset terms) are factorised once, `A = Q R`; for each slope the
//! residual is that of the Coulomb columns `C(v)` against the torques, both with `A`'s span
//! projected out (`C - Q Q^T C`, `y - Q Q^T y`): the same residual vector as the least squares
//! on `[A C(v)]`, at the cost of `C`'s few columns rather than all of them.

use nalgebra::{DMatrix, DVector};

use super::base::BaseParameters;
use super::error::IdentificationError;
use super::estimation::least_squares;
use super::nonlinear::{minimize, Stopping};

/// Starting slopes tried (all joints alike), rad/s or m/s.
pub const SLOPE_GRID: [f64; 8] = [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5];
/// Step of the forward differences in `ln v`.
const STEP: f64 = 1e-5;

/// The slopes' least-squares problem on stacked, weighted rows (`n` joints per sample).
pub struct SlopeProblem {
    n: usize,
    /// Per Coulomb base column, its joint.
    joints: Vec<usize>,
    /// Thin `Q` of the weighted columns that do not depend on the slopes.
    q: DMatrix<f64>,
    /// The weighted torques with `Q`'s span projected out.
    y: DVector<f64>,
    /// `1 / sigma` per joint.
    weight: Vec<f64>,
}

impl SlopeProblem {
    /// The problem of the base regressor (`base` of the full regressor `[w_std friction]`,
    /// `friction` its friction columns at any slope: `fv1..fvN, fc1..fcN` and the offsets),
    /// torques `y`, joint weights `1 / sigma`.
    ///
    /// # Errors
    ///
    /// [`IdentificationError::Estimation`] for mismatched sizes or too few rows.
    pub fn new(
        base: &BaseParameters,
        w_std: &DMatrix<f64>,
        friction: &DMatrix<f64>,
        y: &DVector<f64>,
        sigma: &[f64],
        n: usize,
    ) -> Result<Self, IdentificationError> {
        let m = y.len();
        if w_std.nrows() != m || friction.nrows() != m || sigma.len() != n || n == 0 {
            return Err(IdentificationError::Estimation(format!(
                "friction slopes: {m} torques, {} and {} regressor rows, {} weights for {n} joints",
                w_std.nrows(),
                friction.nrows(),
                sigma.len()
            )));
        }
        let coulomb = w_std.ncols() + n..w_std.ncols() + 2 * n;
        let weight: Vec<f64> = sigma.iter().map(|s| 1.0 / s).collect();
        let (mut fixed, mut joints) = (Vec::new(), Vec::new());
        for c in base.independent() {
            if coulomb.contains(c) {
                joints.push(c - coulomb.start);
            } else {
                fixed.push(*c);
            }
        }
        let mut a = DMatrix::zeros(m, fixed.len());
        for (j, c) in fixed.iter().enumerate() {
            let column = if *c < w_std.ncols() {
                w_std.column(*c)
            } else {
                friction.column(c - w_std.ncols())
            };
            a.set_column(j, &column);
        }
        let mut yw = y.clone();
        for r in 0..m {
            a.row_mut(r).scale_mut(weight[r % n]);
            yw[r] *= weight[r % n];
        }
        if m < fixed.len() + joints.len() {
            return Err(IdentificationError::Estimation(format!(
                "friction slopes: {m} rows for {} unknowns",
                fixed.len() + joints.len()
            )));
        }
        let q = a.qr().q();
        let y = &yw - &q * q.tr_mul(&yw);
        Ok(Self {
            n,
            joints,
            q,
            y,
            weight,
        })
    }

    /// The weighted residual at `slopes` (one per joint) with velocities `qd` (per sample, one
    /// per joint); `None` if the least squares fails.
    #[must_use]
    pub fn residual(&self, slopes: &[f64], qd: &[&[f64]]) -> Option<DVector<f64>> {
        let m = self.y.len();
        let mut c = DMatrix::zeros(m, self.joints.len());
        for (j, i) in self.joints.iter().enumerate() {
            for (k, v) in qd.iter().enumerate() {
                c[(k * self.n + i, j)] = libm::tanh(v[*i] / slopes[*i]) * self.weight[*i];
            }
        }
        let c = &c - &self.q * self.q.tr_mul(&c);
        let x = least_squares(&c, &self.y).ok()?;
        Some(&self.y - c * x)
    }

    /// The slopes minimising the residual: the best of [`SLOPE_GRID`] (all joints alike),
    /// then Levenberg-Marquardt on `ln v` (within `e^-12` to `e^3`); `progress(residuals)`
    /// after every residual computed (the forward differences included).
    pub fn fit(&self, qd: &[&[f64]], progress: &mut dyn FnMut(usize)) -> Vec<f64> {
        let n = self.n;
        let count = core::cell::Cell::new(0);
        let progress = core::cell::RefCell::new(progress);
        let residual = |slopes: &[f64]| {
            count.set(count.get() + 1);
            (progress.borrow_mut())(count.get());
            self.residual(slopes, qd)
        };
        let mut best = (f64::INFINITY, SLOPE_GRID[0]);
        for v in SLOPE_GRID {
            if let Some(r) = residual(&vec![v; n]) {
                if r.norm_squared() < best.0 {
                    best = (r.norm_squared(), v);
                }
            }
        }
        let at = |u: &DVector<f64>| -> Vec<f64> {
            u.iter().map(|x| libm::exp(x.clamp(-12.0, 3.0))).collect()
        };
        let model = |u: &DVector<f64>, with_jacobian: bool| {
            let r = residual(&at(u))?;
            let jac = if with_jacobian {
                let mut j = DMatrix::zeros(r.len(), n);
                for i in 0..n {
                    let mut v = u.clone();
                    v[i] += STEP;
                    let rh = residual(&at(&v))?;
                    j.set_column(i, &((rh - &r) / STEP));
                }
                Some(j)
            } else {
                None
            };
            Some((r, jac))
        };
        // The budget of the crate's former patience of 200: `200 (n + 1)` evaluations.
        let stop = Stopping::tight(200 * (n + 1));
        let u0 = DVector::from_element(n, libm::log(best.1));
        let solution = minimize(&u0, &stop, model);
        at(&solution.x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_projected_residual_is_the_full_least_squares_residual_and_finds_the_slope() {
        // One joint: tau = 2 qd + 0.5 tanh(qd / 0.03) + 0.1 offset, on a base of three
        // columns [fv, fc, fo] (no rigid body).
        let n = 1;
        let qd: Vec<f64> = (0..400)
            .map(|k| 0.3 * libm::sin(f64::from(k) * 0.05))
            .collect();
        let w_std = DMatrix::zeros(qd.len(), 0);
        let mut friction = DMatrix::zeros(qd.len(), 3);
        let mut y = DVector::zeros(qd.len());
        for (k, v) in qd.iter().enumerate() {
            friction[(k, 0)] = *v;
            friction[(k, 1)] = libm::tanh(v / 0.05);
            friction[(k, 2)] = 1.0;
            y[k] = 2.0 * v + 0.5 * libm::tanh(v / 0.03) + 0.1;
        }
        let base =
            BaseParameters::from_stacked(&friction, vec!["fv1".into(), "fc1".into(), "fo1".into()])
                .unwrap();
        let p = SlopeProblem::new(&base, &w_std, &friction, &y, &[0.5], n).unwrap();
        let rows: Vec<&[f64]> = qd.iter().map(core::slice::from_ref).collect();
        // At the slope the columns were built with: the full weighted least squares.
        let full = least_squares(&(&friction * 2.0), &(&y * 2.0)).unwrap();
        let direct = &y * 2.0 - &friction * 2.0 * full;
        let projected = p.residual(&[0.05], &rows).unwrap();
        approx::assert_relative_eq!(projected.norm(), direct.norm(), epsilon = 1e-9);
        // The fitted slope is the true one.
        let slopes = p.fit(&rows, &mut |_| {});
        approx::assert_relative_eq!(slopes[0], 0.03, epsilon = 1e-6);
        assert!(p.residual(&slopes, &rows).unwrap().norm() < 1e-8);
    }
}
