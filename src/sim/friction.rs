//! Joint friction in the plant: viscous plus (smoothed) Coulomb, per joint.

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
        })
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
            self.viscous[i] * qd[i] + self.coulomb[i] * Self::shape(qd[i], self.smoothing)
        })
    }
}
