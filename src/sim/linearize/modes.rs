//! The modes of a discrete closed-loop matrix: eigenvalues, their continuous equivalents and
//! the states each one lives in.
//!
//! ```text
//! z = eig(A),   s = ln(z) / dt,   f = |s| / 2 pi (Hz),   zeta = -Re(s) / |s|
//! participation of state i in mode m:  p_im = |v_im w_im| / sum_i |v_im w_im|
//! ```
//!
//! with `v_m`, `w_m` the right and left eigenvectors (`A v = z v`, `A^T w = z w`), each found
//! by two steps of inverse iteration at the eigenvalue from nalgebra's Schur decomposition.
//! Participation factors do not depend on the units of the states (radians, newton
//! seconds), unlike the entries of an eigenvector.

use nalgebra::{Complex, DMatrix, DVector};

/// A mode closer to `z = 1` than this is neutral: an integrator of a quantity the loop holds
/// at exactly zero (a position integral along a force-controlled direction), which neither
/// grows nor decays.
pub const NEUTRAL_TOLERANCE: f64 = 1e-7;

/// One eigenvalue of the closed loop and what it means.
#[derive(Clone, Debug)]
pub struct Mode {
    /// The discrete eigenvalue `z`.
    pub z: Complex<f64>,
    /// `|z|`: below 1 decays, above 1 grows.
    pub magnitude: f64,
    /// The continuous equivalent `s = ln(z) / dt`, 1/s.
    pub s: Complex<f64>,
    /// `|s| / 2 pi`, Hz.
    pub frequency_hz: f64,
    /// `-Re(s) / |s|` (1 for a real decaying mode, negative when growing).
    pub damping_ratio: f64,
    /// Time constant `-1 / Re(s)`, s (infinite for a neutral mode, negative when growing).
    pub time_constant_s: f64,
    /// The states the mode lives in, with their participation (largest first, summing to
    /// 1 over all states; those above 5 %).
    pub states: Vec<(String, f64)>,
}

impl Mode {
    /// Whether the mode is neutral ([`NEUTRAL_TOLERANCE`]).
    #[must_use]
    pub fn is_neutral(&self) -> bool {
        (self.z - Complex::new(1.0, 0.0)).norm() <= NEUTRAL_TOLERANCE
    }
}

/// Every mode of a closed loop, and the verdict.
#[derive(Clone, Debug)]
pub struct Modes {
    /// One per eigenvalue (a complex pair gives two), by decreasing `|z|`.
    pub modes: Vec<Mode>,
}

impl Modes {
    /// The modes of `a` (discrete, period `dt` s), the states named by `labels`.
    #[must_use]
    pub fn of(a: &DMatrix<f64>, dt: f64, labels: &[String]) -> Self {
        let n = a.nrows();
        let eigenvalues = a.complex_eigenvalues();
        let ac: DMatrix<Complex<f64>> = a.map(|x| Complex::new(x, 0.0));
        let act = ac.transpose();
        let mut modes: Vec<Mode> = eigenvalues
            .iter()
            .map(|&z| {
                let v = inverse_iteration(&ac, z);
                let w = inverse_iteration(&act, z);
                let weights: Vec<f64> = (0..n).map(|i| (v[i] * w[i]).norm()).collect();
                let total: f64 = weights.iter().sum();
                let mut states: Vec<(String, f64)> = labels
                    .iter()
                    .zip(&weights)
                    .map(|(l, p)| (l.clone(), if total > 0.0 { p / total } else { 0.0 }))
                    .filter(|(_, p)| *p >= 0.05)
                    .collect();
                states.sort_by(|x, y| y.1.total_cmp(&x.1));
                let s = z.ln() / dt;
                let norm = s.norm();
                Mode {
                    z,
                    magnitude: z.norm(),
                    s,
                    frequency_hz: norm / (2.0 * core::f64::consts::PI),
                    damping_ratio: if norm > 0.0 { -s.re / norm } else { 1.0 },
                    time_constant_s: -1.0 / s.re,
                    states,
                }
            })
            .collect();
        modes.sort_by(|x, y| y.magnitude.total_cmp(&x.magnitude));
        Self { modes }
    }

    /// Whether every mode decays (neutral ones excepted).
    #[must_use]
    pub fn stable(&self) -> bool {
        self.modes
            .iter()
            .all(|m| m.is_neutral() || m.magnitude < 1.0)
    }

    /// The slowest non-neutral mode: the largest `|z|`.
    #[must_use]
    pub fn slowest(&self) -> Option<&Mode> {
        self.modes.iter().find(|m| !m.is_neutral())
    }

    /// The least damped oscillating mode (smallest damping ratio among complex `z`).
    #[must_use]
    pub fn least_damped(&self) -> Option<&Mode> {
        self.modes
            .iter()
            .filter(|m| !m.is_neutral() && m.z.im.abs() > 1e-12)
            .min_by(|x, y| x.damping_ratio.total_cmp(&y.damping_ratio))
    }
}

/// An eigenvector of `a` for the eigenvalue `z`, by two steps of inverse iteration with a
/// shift a little off `z` (so that `a - shift I` is invertible).
fn inverse_iteration(a: &DMatrix<Complex<f64>>, z: Complex<f64>) -> DVector<Complex<f64>> {
    let n = a.nrows();
    let scale = a.iter().fold(1.0f64, |m, x| m.max(x.norm()));
    let shift = z + Complex::new(1e-10 * scale, 1e-10 * scale);
    let shifted = a - DMatrix::<Complex<f64>>::identity(n, n) * shift;
    let lu = shifted.lu();
    let mut v = DVector::<Complex<f64>>::from_fn(n, |i, _| Complex::new(1.0 + 0.1 * i as f64, 0.3));
    for _ in 0..3 {
        match lu.solve(&v) {
            Some(next) => {
                let norm = next.norm();
                if !(norm.is_finite() && norm > 0.0) {
                    break;
                }
                v = next / Complex::new(norm, 0.0);
            }
            None => break,
        }
    }
    v
}
