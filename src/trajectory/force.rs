//! Desired contact-force profiles of the hybrid force-position trials (Appendix B.3); the
//! thesis's own two are [`crate::robots::scara::thesis::constant_force`] and
//! [`crate::robots::scara::thesis::variable_force`].
//!
//! The thesis's code commands a force along z only, zero during the approach (`j < 0.2`,
//! the first 2 s of the 10 s run) and then either a constant or a slowly varying push:
//!
//! ```text
//! fz_d = 0                         j < 0.2
//! fz_d = -200                      j >= 0.2   (constant case, N)
//! fz_d = -200 - 200 sin(10 j)      j >= 0.2   (variable case, N; j = t / T, T = 10 s)
//! ```
//!
//! The printed eq. 5.13 disagrees with the code; this is the code's version (`docs/thesis.md`,
//! erratum 6). The sign follows the project's convention for `f_ext`: the wrench the tool
//! exerts on the environment, base frame, so a negative `fz` pushes the surface down.

use crate::model::Wrench;

/// A desired contact force along the base z axis as a function of time.
///
/// Zero before `switch_time` (s), then `magnitude` (N) plus, for [`ForceProfile::Variable`],
/// a sine. The result is the desired wrench `[0, 0, fz_d, 0, 0, 0]` (N, N m) that the tool
/// exerts on the environment; negative `fz_d` pushes down. The command steps at
/// `switch_time` (from 0 to `magnitude`, or to `magnitude + amplitude sin(omega
/// switch_time)`), as in the thesis. Parameters are not validated: NaN in gives NaN out.
///
/// # Example
///
/// ```
/// use armdyn::trajectory::ForceProfile;
///
/// let constant = ForceProfile::constant(-200.0, 2.0);
/// assert_eq!(constant.fz(1.0), 0.0);     // approach: no force command
/// assert_eq!(constant.fz(5.0), -200.0);  // on the surface: push down with 200 N
/// let w = constant.wrench(5.0);
/// assert_eq!((w[0], w[2], w[5]), (0.0, -200.0, 0.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceProfile {
    /// `fz_d = 0` for `t < switch_time`, then `magnitude`.
    Constant {
        /// Force after the switch, N (thesis: -200).
        magnitude: f64,
        /// Time at which the command starts, s (thesis: 2).
        switch_time: f64,
    },
    /// `fz_d = 0` for `t < switch_time`, then `magnitude + amplitude sin(omega t)`.
    ///
    /// The thesis writes `-200 - 200 sin(10 j)` with `j = t / T`, `T = 10 s`, that is
    /// `omega = 10 / T = 1 rad/s` on the time `t` of the whole run (not restarted at the
    /// switch).
    Variable {
        /// Mean force after the switch, N (thesis: -200).
        magnitude: f64,
        /// Amplitude of the sine, N (thesis: -200).
        amplitude: f64,
        /// Angular frequency of the sine in time, rad/s (thesis: 1).
        omega: f64,
        /// Time at which the command starts, s (thesis: 2).
        switch_time: f64,
    },
}

impl ForceProfile {
    /// A constant push of `magnitude` N starting at `switch_time` s.
    ///
    /// ```
    /// use armdyn::trajectory::ForceProfile;
    /// let f = ForceProfile::constant(-50.0, 1.0);
    /// assert_eq!((f.fz(0.5), f.fz(1.0)), (0.0, -50.0));
    /// ```
    pub fn constant(magnitude: f64, switch_time: f64) -> Self {
        ForceProfile::Constant {
            magnitude,
            switch_time,
        }
    }

    /// Time at which the force command starts, s.
    ///
    /// ```
    /// use armdyn::trajectory::ForceProfile;
    /// assert_eq!(ForceProfile::constant(-200.0, 2.0).switch_time(), 2.0);
    /// ```
    pub fn switch_time(&self) -> f64 {
        match *self {
            ForceProfile::Constant { switch_time, .. }
            | ForceProfile::Variable { switch_time, .. } => switch_time,
        }
    }

    /// Desired force along the base z axis at time `t` (s), N; negative pushes down.
    ///
    /// ```
    /// use armdyn::trajectory::ForceProfile;
    /// assert_eq!(ForceProfile::constant(-200.0, 2.0).fz(0.0), 0.0);
    /// ```
    pub fn fz(&self, t: f64) -> f64 {
        if t < self.switch_time() {
            return 0.0;
        }
        match *self {
            ForceProfile::Constant { magnitude, .. } => magnitude,
            ForceProfile::Variable {
                magnitude,
                amplitude,
                omega,
                ..
            } => magnitude + amplitude * libm::sin(omega * t),
        }
    }

    /// Desired wrench the tool exerts on the environment at time `t` (s),
    /// `[0, 0, fz_d, 0, 0, 0]` in N and N m, base frame.
    ///
    /// ```
    /// use armdyn::trajectory::ForceProfile;
    /// let w = ForceProfile::constant(-200.0, 2.0).wrench(3.0);
    /// assert_eq!(w, nalgebra::Vector6::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0));
    /// ```
    pub fn wrench(&self, t: f64) -> Wrench {
        Wrench::new(0.0, 0.0, self.fz(t), 0.0, 0.0, 0.0)
    }
}

impl Default for ForceProfile {
    /// 200 N pressing down (`fz = -200 N`) from 2 s: the thesis's constant case.
    fn default() -> Self {
        ForceProfile::constant(-200.0, 2.0)
    }
}
