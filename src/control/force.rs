//! Force laws for the force loop of the hybrid controller (thesis Section 5.3), in
//! Cartesian space: the output is a wrench the actuators should exert through the tool.

use crate::model::Wrench;

/// PI on the force error plus feedforward of the desired force (eq. 5.10), optionally with
/// velocity damping (eq. 5.11):
///
/// ```text
/// f_cmd = f_d + Kfp (f_d - f) + Kfi int(f_d - f) dt - Kvd X_dot
/// ```
///
/// `f` and `f_d` are wrenches the tool exerts on the environment (negative z = pushing
/// down), `X_dot = J qd` the tool's twist. Only the directions given to force control by the
/// selection matrix are used; the integral runs only while a direction is selected for
/// force control, from zero at the switch.
///
/// ```
/// use scara::control::force::ForcePi;
/// let f = ForcePi::thesis_damped();
/// assert_eq!((f.kfp(), f.kfi(), f.kvd()), (20.0, 5.0, 2000.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForcePi {
    kfp: f64,
    kfi: f64,
    kvd: f64,
    integral: Wrench,
}

impl ForcePi {
    /// Gains: `kfp` (dimensionless), `kfi` (1/s), `kvd` (N s/m; 0 for none).
    #[must_use]
    pub fn new(kfp: f64, kfi: f64, kvd: f64) -> Self {
        Self {
            kfp,
            kfi,
            kvd,
            integral: Wrench::zeros(),
        }
    }

    /// The thesis's PI + feedforward: `Kfp = 20`, `Kfi = 5` (Section 5.3.1).
    #[must_use]
    pub fn thesis() -> Self {
        Self::new(20.0, 5.0, 0.0)
    }

    /// The thesis's PI + feedforward + velocity damping: `Kvd = 2000` N s/m (Section 5.3.2).
    #[must_use]
    pub fn thesis_damped() -> Self {
        Self::new(20.0, 5.0, 2000.0)
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

    /// Clears the integral.
    pub fn reset(&mut self) {
        self.integral = Wrench::zeros();
    }

    /// One period of `dt` s: the commanded wrench in the directions where `force_weight`
    /// (the diagonal of `I - S`) is non-zero, zero elsewhere.
    pub fn step(
        &mut self,
        f_d: &Wrench,
        f: &Wrench,
        twist: &Wrench,
        force_weight: &Wrench,
        dt: f64,
    ) -> Wrench {
        let mut out = Wrench::zeros();
        for i in 0..6 {
            if force_weight[i] == 0.0 {
                self.integral[i] = 0.0;
                continue;
            }
            let e = f_d[i] - f[i];
            self.integral[i] += e * dt;
            out[i] = f_d[i] + self.kfp * e + self.kfi * self.integral[i] - self.kvd * twist[i];
        }
        out
    }
}
