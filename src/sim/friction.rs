//! Joint friction in the plant: viscous plus (smoothed) Coulomb, per joint; optionally a
//! Stribeck term and an asymmetric Coulomb level ([`JointFriction::with_stribeck`],
//! [`JointFriction::with_asymmetry`]), forms an identification's friction model lacks.

use crate::model::JointVector;

/// Default width of the Coulomb term's smooth sign, rad/s or m/s.
///
/// `tanh(qd / v)` instead of `sign(qd)`: a true sign is discontinuous at rest, which a
/// fixed-step RK4 cannot integrate; the slope `fc / v` must stay well below `2.8 / h` times
/// the joint inertia for an RK4 step `h`.
pub const DEFAULT_SMOOTHING: f64 = 0.05;

/// `tau_f,i = fv_i qd_i + fc_i tanh(qd_i / v)`: the torque (N m) or force (N) joint `i`'s
/// friction opposes its motion with.
///
/// `fv` in N m s/rad (N s/m for a prismatic joint), `fc` in N m (N), `v` in rad/s (m/s).
/// The identification regressor uses the same shape ([`Self::shape`]), so friction
/// parameters can be identified exactly.
///
/// ```
/// use armdyn::sim::JointFriction;
/// use nalgebra::Vector2;
/// let f = JointFriction::new(Vector2::new(2.0, 0.5), Vector2::new(1.0, 0.0), 0.01).unwrap();
/// let tau = f.torque(&Vector2::new(1.0, -1.0));
/// assert!((tau[0] - 3.0).abs() < 1e-9);
/// assert!((tau[1] + 0.5).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointFriction<const N: usize> {
    viscous: JointVector<N>,
    coulomb: JointVector<N>,
    smoothing: f64,
    /// Stribeck: extra friction at rest `fs_i` (N m or N) and its velocity `vs` (rad/s or
    /// m/s), `None` for none.
    stribeck: Option<(JointVector<N>, f64)>,
    /// Asymmetry `a_i` of the Coulomb level: `fc (1 + a)` moving forward, `fc (1 - a)`
    /// backward; `None` for none.
    asymmetry: Option<JointVector<N>>,
}

/// Friction coefficients that are not finite and non-negative, or a bad smoothing width.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum FrictionError {
    /// A coefficient of joint `0` (from 0) is negative or not finite.
    #[error("joint friction: coefficients must be finite and >= 0 (joint {0})")]
    Coefficient(usize),
    /// The smoothing velocity is not finite and positive.
    #[error("joint friction: the Coulomb smoothing velocity must be finite and > 0")]
    Smoothing,
    /// A Stribeck term of joint `0` (from 0) is negative or not finite, or its velocity is
    /// not finite and positive.
    #[error(
        "joint friction: the Stribeck term must be finite and >= 0, its velocity > 0 (joint {0})"
    )]
    Stribeck(usize),
    /// The Coulomb asymmetry of joint `0` (from 0) is not in `[-1, 1]`.
    #[error("joint friction: the Coulomb asymmetry must be in [-1, 1] (joint {0})")]
    Asymmetry(usize),
}

impl<const N: usize> JointFriction<N> {
    /// Viscous `fv` and Coulomb `fc` coefficients per joint, Coulomb smoothing `v`.
    ///
    /// # Errors
    ///
    /// [`FrictionError`] naming the bad value.
    pub fn new(
        viscous: JointVector<N>,
        coulomb: JointVector<N>,
        smoothing: f64,
    ) -> Result<Self, FrictionError> {
        for i in 0..N {
            let ok = |x: f64| x.is_finite() && x >= 0.0;
            if !ok(viscous[i]) || !ok(coulomb[i]) {
                return Err(FrictionError::Coefficient(i));
            }
        }
        if !(smoothing.is_finite() && smoothing > 0.0) {
            return Err(FrictionError::Smoothing);
        }
        Ok(Self {
            viscous,
            coulomb,
            smoothing,
            stribeck: None,
            asymmetry: None,
        })
    }

    /// This friction plus a Stribeck term `fs_i exp(-(qd_i / vs)^2) tanh(qd_i / v)`: more
    /// friction near rest than the Coulomb level, fading over the velocity `vs`.
    ///
    /// # Errors
    ///
    /// [`FrictionError::Stribeck`] for a negative or non-finite `fs_i` or a `vs` not finite
    /// and positive.
    pub fn with_stribeck(self, fs: JointVector<N>, vs: f64) -> Result<Self, FrictionError> {
        for i in 0..N {
            if !(fs[i].is_finite() && fs[i] >= 0.0 && vs.is_finite() && vs > 0.0) {
                return Err(FrictionError::Stribeck(i));
            }
        }
        Ok(Self {
            stribeck: Some((fs, vs)),
            ..self
        })
    }

    /// This friction with an asymmetric Coulomb level: `fc_i (1 + a_i)` for positive
    /// velocities, `fc_i (1 - a_i)` for negative ones (the term `a_i fc_i tanh^2(qd_i / v)`
    /// added).
    ///
    /// # Errors
    ///
    /// [`FrictionError::Asymmetry`] for an `a_i` outside `[-1, 1]`.
    pub fn with_asymmetry(self, a: JointVector<N>) -> Result<Self, FrictionError> {
        for i in 0..N {
            if !(a[i].is_finite() && a[i].abs() <= 1.0) {
                return Err(FrictionError::Asymmetry(i));
            }
        }
        Ok(Self {
            asymmetry: Some(a),
            ..self
        })
    }

    /// The Stribeck term (`fs`, `vs`), if any.
    #[must_use]
    pub fn stribeck(&self) -> Option<(JointVector<N>, f64)> {
        self.stribeck
    }

    /// The Coulomb asymmetry, if any.
    #[must_use]
    pub fn asymmetry(&self) -> Option<JointVector<N>> {
        self.asymmetry
    }

    /// Viscous coefficients.
    #[must_use]
    pub fn viscous(&self) -> &JointVector<N> {
        &self.viscous
    }

    /// Coulomb coefficients.
    #[must_use]
    pub fn coulomb(&self) -> &JointVector<N> {
        &self.coulomb
    }

    /// Coulomb smoothing velocity, rad/s or m/s.
    #[must_use]
    pub fn smoothing(&self) -> f64 {
        self.smoothing
    }

    /// The smooth sign `tanh(qd / v)` of the Coulomb term, for a regressor column.
    #[must_use]
    pub fn shape(qd: f64, smoothing: f64) -> f64 {
        libm::tanh(qd / smoothing)
    }

    /// The friction torque at joint velocities `qd`.
    #[must_use]
    pub fn torque(&self, qd: &JointVector<N>) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| {
            let s = Self::shape(qd[i], self.smoothing);
            let mut tau = self.viscous[i] * qd[i] + self.coulomb[i] * s;
            if let Some((fs, vs)) = &self.stribeck {
                let r = qd[i] / vs;
                tau += fs[i] * libm::exp(-r * r) * s;
            }
            if let Some(a) = &self.asymmetry {
                tau += a[i] * self.coulomb[i] * s * s;
            }
            tau
        })
    }
}
