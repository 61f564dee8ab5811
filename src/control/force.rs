//! Force laws for the force loop of the hybrid controller (thesis Section 5.3), along the
//! contact normal: the output is the force the actuators should exert through the tool.

/// PI on the force error plus feedforward of the desired force (eq. 5.10), optionally with
/// velocity damping (eq. 5.11), along one task direction (the contact normal `n`):
///
/// ```text
/// f_cmd = f_d + Kfp (f_d - f) + Kfi int(f_d - f) dt - Kvd (n . X_dot)
/// ```
///
/// `f` and `f_d` are the components along `n` of wrenches the tool exerts on the
/// environment (negative = pushing into a surface whose outward normal is `n`), `X_dot = J qd`
/// the tool's velocity. The integral runs only while force is controlled: the hybrid
/// controller resets it out of contact, and may set it at the switch (bumpless transfer).
///
/// ```
/// use armdyn::control::force::ForcePi;
/// let mut f = ForcePi::new(20.0, 5.0, 2000.0);
/// assert_eq!((f.kfp(), f.kfi(), f.kvd()), (20.0, 5.0, 2000.0));
/// // At rest on the reference the command is the feedforward alone.
/// assert_eq!(f.step(-200.0, -200.0, 0.0, 1e-3), -200.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForcePi {
    kfp: f64,
    kfi: f64,
    kvd: f64,
    integral: f64,
}

impl ForcePi {
    /// Gains: `kfp` (dimensionless), `kfi` (1/s), `kvd` (N s/m; 0 for none).
    #[must_use]
    pub fn new(kfp: f64, kfi: f64, kvd: f64) -> Self {
        Self {
            kfp,
            kfi,
            kvd,
            integral: 0.0,
        }
    }

    /// Proportional gain.
    #[must_use]
    pub fn kfp(&self) -> f64 {
        self.kfp
    }

    /// Integral gain, 1/s.
    #[must_use]
    pub fn kfi(&self) -> f64 {
        self.kfi
    }

    /// Velocity damping, N s/m.
    #[must_use]
    pub fn kvd(&self) -> f64 {
        self.kvd
    }

    /// The integral of the force error, N s.
    #[must_use]
    pub fn integral(&self) -> f64 {
        self.integral
    }

    /// Sets the integral, N s (bumpless transfer at a switch).
    pub fn set_integral(&mut self, value: f64) {
        self.integral = value;
    }

    /// Clears the integral.
    pub fn reset(&mut self) {
        self.integral = 0.0;
    }

    /// Conditional integration (anti-windup) after a [`Self::step`] that started from the
    /// integral `integral_before`: if this period's integral increment, exerted along the
    /// normal `n` through the linear rows `j_v` of the Jacobian (`dtau = J_v^T n Kfi dI`),
    /// pushes an actuator already past its limit in `effort_limits` further out, the
    /// integral is restored and `tau - dtau` returned; else `tau` unchanged.
    pub fn without_windup<const N: usize>(
        &mut self,
        j_v: &nalgebra::SMatrix<f64, 3, N>,
        n: &nalgebra::Vector3<f64>,
        tau: nalgebra::SVector<f64, N>,
        integral_before: f64,
        effort_limits: &[f64; N],
    ) -> nalgebra::SVector<f64, N> {
        let increment = self.kfi * (self.integral - integral_before);
        let dtau = j_v.tr_mul(&(n * increment));
        let winds_up = (0..N).any(|i| tau[i].abs() > effort_limits[i] && dtau[i] * tau[i] > 0.0);
        if winds_up {
            self.integral = integral_before;
            tau - dtau
        } else {
            tau
        }
    }

    /// One period of `dt` s: desired `f_d` and measured `f` force along the normal (N),
    /// tool velocity `v_n` along it (m/s); returns the commanded force along it, N.
    pub fn step(&mut self, f_d: f64, f: f64, v_n: f64, dt: f64) -> f64 {
        let e = f_d - f;
        self.integral += e * dt;
        f_d + self.kfp * e + self.kfi * self.integral - self.kvd * v_n
    }
}
