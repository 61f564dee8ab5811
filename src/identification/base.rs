//! Base parameters: the combinations of standard parameters that the joint torques determine
//! (Gautier's numerical method on a stacked regressor).
//!
//! Columns of `W` (the regressor stacked at many random states) are taken link by link, link 1
//! first, and within a link in the order of [`PREFERENCE`] (inertias, then first moments,
//! then the mass); a column is kept when its part orthogonal to the columns already kept is
//! larger than [`RANK_TOLERANCE`] times its norm, otherwise it is a linear combination of
//! them (`w_d = W_kept beta_d`) and its parameter is regrouped into theirs: `pi_b = pi_kept +
//! beta pi_dependent`, `tau = Y_kept pi_b`. This order regroups masses and first moments of
//! link `j` into the inertias and first moments of link `j - 1`, as Khalil's symbolic rules
//! do (`Izz1 + a1^2 m2`). The rank is checked again by an SVD of the column-normalised `W`.

use nalgebra::{DMatrix, DVector};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

use super::error::IdentificationError;
use super::robots::Identifiable;
use super::signals::full_regressor;
use crate::model::JointVector;

/// Relative tolerance of both rank tests (orthogonal residual over column norm; singular
/// value over the largest, columns normalised).
pub const RANK_TOLERANCE: f64 = 1e-8;
/// Coefficients of a combination smaller than this (absolute) are rounding, not geometry.
pub const COEFFICIENT_ZERO: f64 = 1e-10;

/// Order in which a link's parameters are offered as base parameters (name prefixes).
pub const PREFERENCE: [&str; 10] = [
    "Izz", "Ixx", "Iyy", "Ixy", "Ixz", "Iyz", "m cx", "m cy", "m cz", "m",
];

/// Sort key of a parameter name: `(link, rank)`; friction (`fv`, `fc`) after every link.
fn preference(name: &str) -> (usize, usize) {
    let digits: String = name
        .chars()
        .rev()
        .take_while(char::is_ascii_digit)
        .collect();
    let link: usize = digits
        .chars()
        .rev()
        .collect::<String>()
        .parse()
        .unwrap_or(0);
    if name.starts_with("fv") {
        return (usize::MAX, link);
    }
    if name.starts_with("fc") {
        return (usize::MAX, 1000 + link);
    }
    if name.starts_with("fo") {
        return (usize::MAX, 2000 + link);
    }
    let generic: String = name
        .split_whitespace()
        .map(|w| w.trim_end_matches(|c: char| c.is_ascii_digit()))
        .collect::<Vec<_>>()
        .join(" ");
    let rank = PREFERENCE
        .iter()
        .position(|p| *p == generic)
        .unwrap_or(PREFERENCE.len());
    (link, rank)
}

/// The identifiable combinations of a parameter vector.
#[derive(Clone, Debug, PartialEq)]
pub struct BaseParameters {
    names: Vec<String>,
    independent: Vec<usize>,
    dependent: Vec<usize>,
    beta: DMatrix<f64>,
    svd_rank: usize,
    rows: usize,
}

impl BaseParameters {
    /// From a stacked regressor `w` (rows: samples, columns: the parameters named `names`).
    ///
    /// # Errors
    ///
    /// [`IdentificationError::RankMismatch`] if the SVD rank disagrees with the column
    /// selection; [`IdentificationError::Estimation`] if `w` is empty or `names` has another
    /// length.
    pub fn from_stacked(w: &DMatrix<f64>, names: Vec<String>) -> Result<Self, IdentificationError> {
        if w.ncols() != names.len() || w.nrows() < w.ncols() || w.ncols() == 0 {
            return Err(IdentificationError::Estimation(format!(
                "stacked regressor {} x {} for {} names: needs at least as many rows as columns",
                w.nrows(),
                w.ncols(),
                names.len()
            )));
        }
        let largest = (0..w.ncols())
            .map(|j| w.column(j).norm())
            .fold(0.0, f64::max);
        let mut basis: Vec<DVector<f64>> = Vec::new();
        let (mut independent, mut dependent) = (Vec::new(), Vec::new());
        let mut order: Vec<usize> = (0..w.ncols()).collect();
        order.sort_by_key(|j| preference(&names[*j]));
        for j in order {
            let col = w.column(j).into_owned();
            let norm = col.norm();
            if norm <= RANK_TOLERANCE * largest {
                dependent.push(j);
                continue;
            }
            let mut r = col.clone();
            // Modified Gram-Schmidt, twice, against the kept columns.
            for _ in 0..2 {
                for b in &basis {
                    let d = b.dot(&r);
                    r.axpy(-d, b, 1.0);
                }
            }
            let rn = r.norm();
            if rn > RANK_TOLERANCE * norm {
                basis.push(r / rn);
                independent.push(j);
            } else {
                dependent.push(j);
            }
        }
        let mut normalised = w.clone();
        for j in 0..w.ncols() {
            let n = w.column(j).norm();
            if n > RANK_TOLERANCE * largest {
                normalised.column_mut(j).scale_mut(1.0 / n);
            } else {
                normalised.column_mut(j).fill(0.0);
            }
        }
        let sv = normalised.singular_values();
        let top = sv.max();
        let svd_rank = sv.iter().filter(|s| **s > RANK_TOLERANCE * top).count();
        if svd_rank != independent.len() {
            return Err(IdentificationError::RankMismatch {
                greedy: independent.len(),
                svd: svd_rank,
                tolerance: RANK_TOLERANCE,
            });
        }
        let w1 = w.select_columns(&independent);
        let w2 = w.select_columns(&dependent);
        let mut beta = if dependent.is_empty() {
            DMatrix::zeros(independent.len(), 0)
        } else {
            w1.clone()
                .svd(true, true)
                .solve(&w2, 0.0)
                .map_err(|e| IdentificationError::Estimation(e.to_string()))?
        };
        beta.apply(|b| {
            if b.abs() < COEFFICIENT_ZERO {
                *b = 0.0;
            }
        });
        Ok(Self {
            names,
            independent,
            dependent,
            beta,
            svd_rank,
            rows: w.nrows(),
        })
    }

    /// Base parameters of `robot` from its regressor at `states` random states (positions
    /// uniform within the joint limits, velocities within +-2, accelerations within +-5 per
    /// unit), plus the friction columns when `friction_smoothing` is given.
    ///
    /// # Errors
    ///
    /// As [`Self::from_stacked`].
    pub fn of_robot<const N: usize, R: Identifiable<N>>(
        robot: &R,
        friction_smoothing: Option<f64>,
        states: usize,
        seed: u64,
    ) -> Result<Self, IdentificationError> {
        let mut names = robot.parameter_names();
        if friction_smoothing.is_some() {
            names.extend(super::signals::friction_names(N));
        }
        Self::of_regressor(robot, names, states, seed, |q, qd, qdd| {
            full_regressor(robot, q, qd, qdd, friction_smoothing)
        })
    }

    /// Base parameters of the parameters `names` whose regressor `full(q, qd, qdd)` (`N` rows,
    /// one column per name) is stacked at `states` random states as in [`Self::of_robot`].
    ///
    /// # Errors
    ///
    /// As [`Self::from_stacked`].
    pub fn of_regressor<const N: usize, R: Identifiable<N>>(
        robot: &R,
        names: Vec<String>,
        states: usize,
        seed: u64,
        full: impl Fn(&JointVector<N>, &JointVector<N>, &JointVector<N>) -> DMatrix<f64>,
    ) -> Result<Self, IdentificationError> {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
        let (lo, hi) = (robot.lower_limits(), robot.upper_limits());
        let mut w = DMatrix::zeros(states * N, names.len());
        for k in 0..states {
            let q = JointVector::<N>::from_fn(|i, _| {
                let (l, h) = if lo[i].is_finite() && hi[i].is_finite() {
                    (lo[i], hi[i])
                } else {
                    (-core::f64::consts::PI, core::f64::consts::PI)
                };
                rng.random_range(l..=h)
            });
            let qd = JointVector::<N>::from_fn(|_, _| rng.random_range(-2.0..=2.0));
            let qdd = JointVector::<N>::from_fn(|_, _| rng.random_range(-5.0..=5.0));
            let y = full(&q, &qd, &qdd);
            if y.ncols() != names.len() {
                return Err(IdentificationError::Estimation(format!(
                    "regressor of {} columns for {} parameter names",
                    y.ncols(),
                    names.len()
                )));
            }
            w.view_mut((k * N, 0), (N, names.len())).copy_from(&y);
        }
        Self::from_stacked(&w, names)
    }

    /// How many base parameters.
    #[must_use]
    pub fn count(&self) -> usize {
        self.independent.len()
    }

    /// The rank of the column-normalised stacked regressor by SVD (equal to [`Self::count`]).
    #[must_use]
    pub fn svd_rank(&self) -> usize {
        self.svd_rank
    }

    /// Rows of the stacked regressor the selection was made on.
    #[must_use]
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Indices of the parameters kept (each base parameter's leading parameter).
    #[must_use]
    pub fn independent(&self) -> &[usize] {
        &self.independent
    }

    /// Names of every parameter of the full vector.
    #[must_use]
    pub fn parameter_names(&self) -> &[String] {
        &self.names
    }

    /// Parameters that appear in no base parameter: they do not affect the torques.
    #[must_use]
    pub fn unidentifiable(&self) -> Vec<&str> {
        self.dependent
            .iter()
            .enumerate()
            .filter(|(d, _)| self.beta.column(*d).iter().all(|b| *b == 0.0))
            .map(|(_, j)| self.names[*j].as_str())
            .collect()
    }

    /// Each base parameter as a readable combination, e.g. `Izz1 + 0.16 m2 + 0.8 m2 cx2`.
    #[must_use]
    pub fn names(&self) -> Vec<String> {
        (0..self.count())
            .map(|i| {
                let mut s = self.names[self.independent[i]].clone();
                for (d, j) in self.dependent.iter().enumerate() {
                    let b = self.beta[(i, d)];
                    if b == 0.0 {
                        continue;
                    }
                    let (sign, mag) = if b < 0.0 { ("-", -b) } else { ("+", b) };
                    let coefficient = format_coefficient(mag);
                    s.push_str(&format!(" {sign} {coefficient}{}", self.names[*j]));
                }
                s
            })
            .collect()
    }

    /// The base parameters of a full parameter vector, `pi_b = pi_kept + beta pi_dependent`.
    #[must_use]
    pub fn project(&self, pi: &DVector<f64>) -> DVector<f64> {
        let kept = pi.select_rows(&self.independent);
        if self.dependent.is_empty() {
            return kept;
        }
        kept + &self.beta * pi.select_rows(&self.dependent)
    }

    /// The base regressor: the kept columns of a full regressor.
    #[must_use]
    pub fn select(&self, y: &DMatrix<f64>) -> DMatrix<f64> {
        y.select_columns(&self.independent)
    }

    /// A full parameter vector with the same torques as `pi_b`: the kept parameters equal to
    /// the base ones, every regrouped parameter zero.
    #[must_use]
    pub fn expand(&self, pi_b: &DVector<f64>) -> DVector<f64> {
        let mut pi = DVector::zeros(self.names.len());
        for (i, j) in self.independent.iter().enumerate() {
            pi[*j] = pi_b[i];
        }
        pi
    }
}

/// `0.16 ` for 0.16, nothing for 1; ten significant digits at most.
fn format_coefficient(c: f64) -> String {
    if (c - 1.0).abs() < 1e-12 {
        return String::new();
    }
    let digits = 9 - libm::floor(libm::log10(c)) as i32;
    let scale = libm::pow(10.0, f64::from(digits.clamp(0, 15)));
    format!("{} ", libm::round(c * scale) / scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Planar2, Scara};

    #[test]
    fn planar2_base_torques_equal_standard_ones() {
        let b = BaseParameters::of_robot(&Planar2, None, 60, 1).unwrap();
        assert_eq!(b.count(), b.svd_rank());
        let pi = Planar2.standard_parameters();
        let pib = b.project(&pi);
        for k in 0..10 {
            let q = nalgebra::Vector2::new(0.1 * f64::from(k), -0.3);
            let qd = nalgebra::Vector2::new(0.5, 0.2 * f64::from(k));
            let qdd = nalgebra::Vector2::new(1.0, -0.7);
            let y = Planar2.regressor(&q, &qd, &qdd);
            approx::assert_relative_eq!(&y * &pi, b.select(&y) * &pib, epsilon = 1e-10);
        }
        // The first link's zz absorbs the second link's mass (a1 = 0.5 m): Khalil's regrouping.
        assert!(
            b.names()
                .iter()
                .any(|n| n.starts_with("Izz1 ") && n.contains("0.25 m2")),
            "{:?}",
            b.names()
        );
        assert_eq!(b.count(), 6, "{:?}", b.names());
    }

    #[test]
    fn scara_base_torques_equal_standard_ones_and_expansion_keeps_them() {
        let b = BaseParameters::of_robot(&Scara, Some(0.01), 100, 2).unwrap();
        let mut pi = Scara.standard_parameters().resize_vertically(48, 0.0);
        pi.rows_mut(40, 8)
            .copy_from_slice(&[1.0, 2.0, 3.0, 4.0, 0.5, 0.6, 0.7, 0.8]);
        let q = nalgebra::Vector4::new(0.4, -1.1, 0.2, 0.3);
        let qd = nalgebra::Vector4::new(-0.5, 0.8, 0.1, 2.0);
        let qdd = nalgebra::Vector4::new(1.5, -0.3, 0.2, 0.9);
        let y = full_regressor(&Scara, &q, &qd, &qdd, Some(0.01));
        let tau = &y * &pi;
        approx::assert_relative_eq!(tau, b.select(&y) * b.project(&pi), epsilon = 1e-9);
        approx::assert_relative_eq!(tau, &y * b.expand(&b.project(&pi)), epsilon = 1e-9);
        // A dependent column is refused by a tighter selection: the rank is stable.
        assert_eq!(b.names().len(), b.count());
        assert!(b.names().iter().all(|n| !n.contains("NaN")));
    }

    #[test]
    fn coefficients_read_well() {
        assert_eq!(format_coefficient(1.0), "");
        assert_eq!(format_coefficient(0.16), "0.16 ");
        assert_eq!(format_coefficient(0.4 * 0.4), "0.16 ");
    }
}
