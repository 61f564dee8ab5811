//! Gain design from the model, as in thesis Chapter 4.
//!
//! Each joint is treated as a decoupled double integrator `m_i s^2` (eq. 4.4–4.8); a PID
//! loop around it has the characteristic polynomial `m s^3 + Kd s^2 + Kp s + Ki`
//! (eq. 4.9–4.12). Placing its roots at `p1, p2, p3` gives
//! `Kd = -m (p1 + p2 + p3)`, `Kp = m (p1 p2 + p1 p3 + p2 p3)`, `Ki = -m p1 p2 p3`;
//! for the thesis's poles -8, -9, -10 that is `Kp = 242 m`, `Ki = 720 m`, `Kd = 27 m`
//! (eq. 4.13–4.15).

use crate::model::JointVector;

/// Proportional, integral and derivative gains per joint.
///
/// Units per joint: `kp` in N m/rad (or N/m), `ki` in N m/(rad s), `kd` in N m s/rad.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PidGains<const N: usize> {
    /// Proportional gains.
    pub kp: JointVector<N>,
    /// Integral gains.
    pub ki: JointVector<N>,
    /// Derivative gains.
    pub kd: JointVector<N>,
}

impl<const N: usize> PidGains<N> {
    /// Gains placing each joint's closed-loop poles at `poles` (all real and negative), for
    /// the effective masses `masses` (kg m^2 or kg): thesis eq. 4.9–4.15.
    ///
    /// ```
    /// use armdyn::control::gains::PidGains;
    /// use nalgebra::Vector4;
    /// let g = PidGains::from_poles(&Vector4::new(5.57, 1.12, 4.94, 0.0025), [-8.0, -9.0, -10.0]);
    /// assert!((g.kp[0] - 1347.94).abs() < 1e-9); // eq. 4.15
    /// assert!((g.ki[1] - 806.4).abs() < 1e-9);
    /// assert!((g.kd[3] - 0.0675).abs() < 1e-12);
    /// ```
    #[must_use]
    pub fn from_poles(masses: &JointVector<N>, poles: [f64; 3]) -> Self {
        let [p1, p2, p3] = poles;
        let s1 = -(p1 + p2 + p3);
        let s2 = p1 * p2 + p1 * p3 + p2 * p3;
        let s3 = -(p1 * p2 * p3);
        Self {
            kp: masses * s2,
            ki: masses * s3,
            kd: masses * s1,
        }
    }
}

/// `x` rounded to `digits` significant figures (the thesis computed its gains from the mass
/// matrix as printed, eq. 3.67 / 4.2 / 4.18, i.e. to three significant figures).
///
/// ```
/// use armdyn::control::gains::round_significant;
/// assert_eq!(round_significant(5.566449, 3), 5.57);
/// assert_eq!(round_significant(0.0025, 3), 0.0025);
/// ```
#[must_use]
pub fn round_significant(x: f64, digits: u32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let magnitude = libm::floor(libm::log10(libm::fabs(x)));
    let scale = libm::pow(10.0, f64::from(digits as i32 - 1) - magnitude);
    libm::round(x * scale) / scale
}

/// How the effective masses for gain design are taken from the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MassRounding {
    /// As the thesis: the model's values rounded to three significant figures (default;
    /// reproduces eq. 4.15 and 4.22).
    #[default]
    Thesis,
    /// The model's values unrounded.
    Exact,
}

impl MassRounding {
    /// Applies the rounding to every entry.
    #[must_use]
    pub fn apply<const N: usize>(self, m: &JointVector<N>) -> JointVector<N> {
        match self {
            Self::Thesis => m.map(|x| round_significant(x, 3)),
            Self::Exact => *m,
        }
    }
}
