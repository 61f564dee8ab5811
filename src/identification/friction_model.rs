//! Joint friction and torque offset terms of an identification from a log, linear in their
//! coefficients once the Coulomb shape is fixed.
//!
//! Per joint `i`, the torque the regressor adds to the rigid-body model is
//!
//! ```text
//! tau_f,i = fv_i qd_i + fc_i s(qd_i) + fo_i
//! ```
//!
//! with `s = sign` ([`FrictionModel::ViscousCoulomb`]) or `s(v) = tanh(v / v_i)`
//! ([`FrictionModel::Smooth`], the slope `v_i` fitted per joint as in Gaz et al., RA-L 2019,
//! by [`super::from_log`]), and `fo_i` a constant offset of the torque measurement (optional).
//! Columns in the order `fv1..fvN`, `fc1..fcN`, `fo1..foN`.

use nalgebra::DMatrix;

/// Which friction model is fitted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrictionModel {
    /// No friction terms.
    None,
    /// Viscous plus Coulomb, `fv qd + fc sign(qd)`.
    ViscousCoulomb,
    /// Viscous plus smooth Coulomb, `fv qd + fc tanh(qd / v)`, `v` fitted per joint.
    Smooth,
}

impl FrictionModel {
    /// The name used on the command line and in files.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::ViscousCoulomb => "viscous-coulomb",
            Self::Smooth => "smooth",
        }
    }
}

/// The friction and offset terms of an `n`-joint identification.
#[derive(Clone, Debug, PartialEq)]
pub struct FrictionTerms {
    /// The friction model.
    pub model: FrictionModel,
    /// Whether a constant torque offset per joint is fitted.
    pub offset: bool,
    /// Smooth-Coulomb slope velocity per joint, rad/s or m/s (used by [`FrictionModel::Smooth`]).
    pub slopes: Vec<f64>,
}

impl FrictionTerms {
    /// Terms for `n` joints, slopes `slope` (rad/s or m/s) until fitted.
    #[must_use]
    pub fn new(model: FrictionModel, offset: bool, n: usize, slope: f64) -> Self {
        Self {
            model,
            offset,
            slopes: vec![slope; n],
        }
    }

    /// Terms per joint (0 to 3).
    #[must_use]
    pub fn per_joint(&self) -> usize {
        let f = match self.model {
            FrictionModel::None => 0,
            FrictionModel::ViscousCoulomb | FrictionModel::Smooth => 2,
        };
        f + usize::from(self.offset)
    }

    /// Names of the coefficients, `fv1..fvN`, `fc1..fcN`, `fo1..foN` as present.
    #[must_use]
    pub fn names(&self) -> Vec<String> {
        let n = self.slopes.len();
        let mut out = Vec::new();
        if self.model != FrictionModel::None {
            out.extend((1..=n).map(|j| format!("fv{j}")));
            out.extend((1..=n).map(|j| format!("fc{j}")));
        }
        if self.offset {
            out.extend((1..=n).map(|j| format!("fo{j}")));
        }
        out
    }

    /// The Coulomb shape of joint `i` at velocity `v`.
    #[must_use]
    pub fn shape(&self, i: usize, v: f64) -> f64 {
        match self.model {
            FrictionModel::Smooth => libm::tanh(v / self.slopes[i]),
            _ => {
                if v > 0.0 {
                    1.0
                } else if v < 0.0 {
                    -1.0
                } else {
                    0.0
                }
            }
        }
    }

    /// The `n x (per_joint n)` columns at joint velocities `qd`.
    #[must_use]
    pub fn columns(&self, qd: &[f64]) -> DMatrix<f64> {
        let n = self.slopes.len();
        let mut c = DMatrix::zeros(n, self.per_joint() * n);
        let mut at = 0;
        if self.model != FrictionModel::None {
            for i in 0..n {
                c[(i, i)] = qd[i];
                c[(i, n + i)] = self.shape(i, qd[i]);
            }
            at = 2 * n;
        }
        if self.offset {
            for i in 0..n {
                c[(i, at + i)] = 1.0;
            }
        }
        c
    }

    /// The friction and offset torque of joint `i` at velocity `v` with coefficients `x`
    /// (in the order of [`Self::names`]).
    #[must_use]
    pub fn torque(&self, x: &[f64], i: usize, v: f64) -> f64 {
        let n = self.slopes.len();
        let mut t = 0.0;
        let mut at = 0;
        if self.model != FrictionModel::None {
            t += x[i] * v + x[n + i] * self.shape(i, v);
            at = 2 * n;
        }
        if self.offset {
            t += x[at + i];
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_times_coefficients_are_the_torque() {
        let mut terms = FrictionTerms::new(FrictionModel::Smooth, true, 2, 0.05);
        terms.slopes[1] = 0.2;
        assert_eq!(terms.names(), ["fv1", "fv2", "fc1", "fc2", "fo1", "fo2"]);
        let x = [0.5, 0.7, 2.0, 3.0, -0.1, 0.2];
        let qd = [0.03, -0.4];
        let c = terms.columns(&qd);
        for i in 0..2 {
            let from_columns: f64 = (0..6).map(|k| c[(i, k)] * x[k]).sum();
            approx::assert_relative_eq!(from_columns, terms.torque(&x, i, qd[i]), epsilon = 1e-15);
        }
        let sign = FrictionTerms::new(FrictionModel::ViscousCoulomb, false, 1, 0.05);
        assert_eq!(sign.torque(&[1.0, 2.0], 0, -0.001), -0.001 - 2.0);
        assert_eq!(
            FrictionTerms::new(FrictionModel::None, false, 3, 0.1).per_joint(),
            0
        );
    }
}
