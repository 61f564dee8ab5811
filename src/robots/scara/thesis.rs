//! The thesis's Cartesian references, with analytic first and second derivatives.
//!
//! All three are written in the normalised time `j = t / T` with `T = 10 s`
//! ([`THESIS_DURATION`]), as in the thesis's MATLAB code (Appendix B.2 and B.3), and keep the
//! yaw at 0. Where the printed equations (5.2, 5.3) disagree with the code, the code's
//! versions are used (`docs/thesis.md`, erratum 6, and section 5):
//!
//! | reference | x (m) | y (m) | z (m) |
//! |---|---|---|---|
//! | [`PositionTest`] (eq. 4.16) | `0.8 - 0.4 j - 0.05 sin(4 pi j)` | `-0.2 j + 0.15 sin(1.5 pi j)` | `0.25 - 0.1 j - 0.005 sin(15 pi j)` |
//! | [`ContactTest`], `j < 0.2` (B.3) | `0.8 - 1.5 j` | `-1.5 j` | `0.25 - j (0.25 - z_rs) / 0.2` |
//! | [`ContactTest`], `j >= 0.2` (B.3) | `0.5` | `-0.3 + 0.75 (j - 0.2)` | `z_rs - 0.025 sin(10 pi (j - 0.2))` |
//! | [`ThreeZone`] (B.2, commented) | `0.25` | `-0.4 + 0.8 j` | `0.05 + 0.15 j + 0.025 sin(10 pi j)` |
//!
//! Derivatives with respect to time follow from `d/dt = (1/T) d/dj`. Outside `[0, T]` the
//! time is clamped (the [`CartesianTrajectory`] contract): the reference holds its end
//! values, including the end velocity and acceleration.

use core::f64::consts::PI;

use nalgebra::Vector3;

use crate::target::CartesianTarget;
use crate::trajectory::CartesianTrajectory;
use crate::trajectory::ForceProfile;

/// Length of every thesis trial, `T = 10 s` (Appendix B, `trial_time = 10`).
pub const THESIS_DURATION: f64 = 10.0;

/// Height of the thesis's reaction surface, `z_rs = 0.13 m` (Section 5.1, `rs_zbase`).
pub const THESIS_SURFACE_Z: f64 = 0.13;

/// Clamps `t` into `[0, T]` and returns `j = t / T`. NaN stays NaN.
#[inline]
fn normalised_time(t: f64) -> f64 {
    t.clamp(0.0, THESIS_DURATION) / THESIS_DURATION
}

/// `a sin(w j)` and its first two derivatives with respect to `j`.
#[inline]
fn sine(a: f64, w: f64, j: f64) -> [f64; 3] {
    let (s, c) = (libm::sin(w * j), libm::cos(w * j));
    [a * s, a * w * c, -a * w * w * s]
}

/// Builds a target at yaw 0 from `[value, d/dj, d2/dj2]` per axis, scaling the derivatives
/// to time (`1/T`, `1/T^2`).
#[inline]
fn target_from_j(x: [f64; 3], y: [f64; 3], z: [f64; 3]) -> CartesianTarget {
    let (s1, s2) = (
        1.0 / THESIS_DURATION,
        1.0 / (THESIS_DURATION * THESIS_DURATION),
    );
    CartesianTarget::planar(
        Vector3::new(x[0], y[0], z[0]),
        0.0,
        Vector3::new(x[1], y[1], z[1]) * s1,
        0.0,
        Vector3::new(x[2], y[2], z[2]) * s2,
        0.0,
    )
}

/// The position-control test path, thesis eq. 4.16 (Appendix B.2), `T = 10 s`.
///
/// ```text
/// x = 0.8 - 0.4 j - 0.05 sin(4 pi j)
/// y = -0.2 j + 0.15 sin(1.5 pi j)          j = t / T, metres, yaw = 0
/// z = 0.25 - 0.1 j - 0.005 sin(15 pi j)
/// ```
///
/// It starts at `(0.8, 0, 0.25)`, with the arm stretched (`q2 = 0`, a singular
/// configuration), and according to the thesis stays where both elbow configurations work.
///
/// # Example
///
/// ```
/// use armdyn::trajectory::CartesianTrajectory;
/// use armdyn::robots::scara::thesis::PositionTest;
///
/// let r = PositionTest::new().at(10.0);
/// // j = 1: x = 0.4, y = -0.2 + 0.15 sin(1.5 pi) = -0.35, z = 0.15.
/// assert!((r.position - nalgebra::Vector3::new(0.4, -0.35, 0.15)).norm() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PositionTest;

impl PositionTest {
    /// The thesis's position test, `T = 10 s`.
    ///
    /// ```
    /// use armdyn::trajectory::CartesianTrajectory;
    /// use armdyn::robots::scara::thesis::PositionTest;
    /// assert_eq!(PositionTest::new().duration(), 10.0);
    /// ```
    pub fn new() -> Self {
        PositionTest
    }
}

impl CartesianTrajectory for PositionTest {
    fn duration(&self) -> f64 {
        THESIS_DURATION
    }

    fn at(&self, t: f64) -> CartesianTarget {
        let j = normalised_time(t);
        let sx = sine(-0.05, 4.0 * PI, j);
        let sy = sine(0.15, 1.5 * PI, j);
        let sz = sine(-0.005, 15.0 * PI, j);
        target_from_j(
            [0.8 - 0.4 * j + sx[0], -0.4 + sx[1], sx[2]],
            [-0.2 * j + sy[0], -0.2 + sy[1], sy[2]],
            [0.25 - 0.1 * j + sz[0], -0.1 + sz[1], sz[2]],
        )
    }
}

/// The hybrid force-position test path (Appendix B.3, "RS test line"), `T = 10 s`.
///
/// A straight approach to the reaction surface for `j < 0.2` (the first 2 s), then a line
/// across it in y with a small sinusoidal dip in z:
///
/// ```text
/// j < 0.2:   x = 0.8 - 1.5 j,   y = -1.5 j,                  z = 0.25 - j (0.25 - z_rs) / 0.2
/// j >= 0.2:  x = 0.5,           y = -0.3 + 0.75 (j - 0.2),   z = z_rs - 0.025 sin(10 pi (j - 0.2))
/// ```
///
/// The printed eq. 5.2/5.3 (with `sin(t/T)` in place of `j`) disagree with this, the code's
/// version (`docs/thesis.md`, erratum 6).
///
/// The position is continuous at `j = 0.2` (`(0.5, -0.3, z_rs)`), but the velocity jumps
/// there: from `(-0.15, -0.15, -(0.25 - z_rs)/2)` m/s to `(0, 0.075, -0.025 pi)` m/s with the
/// thesis values. [`CartesianTrajectory::at`] returns the velocity and acceleration of the
/// piece active at `t` (the second piece from `t = 0.2 T` on, as the code's `j < 0.2` test);
/// nothing smooths the jump.
///
/// # Example
///
/// ```
/// use armdyn::trajectory::CartesianTrajectory;
/// use armdyn::robots::scara::thesis::ContactTest;
///
/// let reference = ContactTest::thesis();
/// let before = reference.at(1.999_999);
/// let after = reference.at(2.0);
/// assert!((before.position - after.position).norm() < 1e-6); // continuous position
/// assert!((before.velocity.x + 0.15).abs() < 1e-12);           // approach: -0.15 m/s in x
/// assert_eq!(after.velocity.x, 0.0);                            // on the surface: x held
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactTest {
    /// Height of the reaction surface `z_rs`, m (thesis: 0.13).
    pub z_surface: f64,
}

impl ContactTest {
    /// Normalised time `j` at which the path reaches the surface and changes piece (0.2).
    pub const SWITCH_FRACTION: f64 = 0.2;

    /// The contact test against a surface at height `z_surface` (m).
    ///
    /// ```
    /// use armdyn::trajectory::CartesianTrajectory;
    /// use armdyn::robots::scara::thesis::ContactTest;
    /// let reference = ContactTest::new(0.1);
    /// assert!((reference.at(2.0).position.z - 0.1).abs() < 1e-12);
    /// ```
    pub fn new(z_surface: f64) -> Self {
        ContactTest { z_surface }
    }

    /// The thesis's contact test, `z_rs = 0.13 m` ([`THESIS_SURFACE_Z`]).
    ///
    /// ```
    /// use armdyn::robots::scara::thesis::ContactTest;
    /// assert_eq!(ContactTest::thesis().z_surface, 0.13);
    /// ```
    pub fn thesis() -> Self {
        ContactTest::new(THESIS_SURFACE_Z)
    }

    /// The time at which the path reaches the surface, `0.2 T = 2 s`.
    ///
    /// ```
    /// use armdyn::robots::scara::thesis::ContactTest;
    /// assert_eq!(ContactTest::thesis().switch_time(), 2.0);
    /// ```
    pub fn switch_time(&self) -> f64 {
        Self::SWITCH_FRACTION * THESIS_DURATION
    }
}

impl Default for ContactTest {
    /// Same as [`ContactTest::thesis`].
    fn default() -> Self {
        ContactTest::thesis()
    }
}

impl CartesianTrajectory for ContactTest {
    fn duration(&self) -> f64 {
        THESIS_DURATION
    }

    fn at(&self, t: f64) -> CartesianTarget {
        let j = normalised_time(t);
        let zs = self.z_surface;
        if j < Self::SWITCH_FRACTION {
            let dz = -(0.25 - zs) / Self::SWITCH_FRACTION;
            target_from_j(
                [0.8 - 1.5 * j, -1.5, 0.0],
                [-1.5 * j, -1.5, 0.0],
                [0.25 + j * dz, dz, 0.0],
            )
        } else {
            let u = j - Self::SWITCH_FRACTION;
            let sz = sine(-0.025, 10.0 * PI, u);
            target_from_j(
                [0.5, 0.0, 0.0],
                [-0.3 + 0.75 * u, 0.75, 0.0],
                [zs + sz[0], sz[1], sz[2]],
            )
        }
    }
}

/// The "squiggle within three areas" path of the workspace trial (Appendix B.2, commented
/// out in the code; thesis Section 4.4), `T = 10 s`.
///
/// ```text
/// x = 0.25,   y = -0.4 + 0.8 j,   z = 0.05 + 0.15 j + 0.025 sin(10 pi j)
/// ```
///
/// A line across the base at 0.25 m in front of it, so close that at its ends only one
/// elbow configuration respects the limit of joint 1: with the thesis limits the start
/// (`y = -0.4`) is reachable elbow-down only (`q2 < 0`), the middle by both and the end
/// (`y = 0.4`) elbow-up only, so the elbow has to change during the run.
///
/// # Example
///
/// ```
/// use armdyn::trajectory::CartesianTrajectory;
/// use armdyn::robots::scara::thesis::ThreeZone;
///
/// let r = ThreeZone::new().at(5.0);
/// assert!((r.position - nalgebra::Vector3::new(0.25, 0.0, 0.125)).norm() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ThreeZone;

impl ThreeZone {
    /// The thesis's three-zone path, `T = 10 s`.
    ///
    /// ```
    /// use armdyn::trajectory::CartesianTrajectory;
    /// use armdyn::robots::scara::thesis::ThreeZone;
    /// assert_eq!(ThreeZone::new().at(0.0).position.y, -0.4);
    /// ```
    pub fn new() -> Self {
        ThreeZone
    }
}

impl CartesianTrajectory for ThreeZone {
    fn duration(&self) -> f64 {
        THESIS_DURATION
    }

    fn at(&self, t: f64) -> CartesianTarget {
        let j = normalised_time(t);
        let sz = sine(0.025, 10.0 * PI, j);
        target_from_j(
            [0.25, 0.0, 0.0],
            [-0.4 + 0.8 * j, 0.8, 0.0],
            [0.05 + 0.15 * j + sz[0], 0.15 + sz[1], sz[2]],
        )
    }
}

/// The thesis's commanded push, N (`-200`: the tool presses down on the surface).
pub const THESIS_FORCE: f64 = -200.0;

/// The thesis's time at which the force command starts, s (`j = 0.2` of `T = 10 s`).
pub const THESIS_FORCE_SWITCH_TIME: f64 = 0.2 * THESIS_DURATION;

/// The thesis's constant case: 0 N for `t < 2 s`, then -200 N.
///
/// ```
/// use armdyn::robots::scara::thesis::{constant_force, variable_force};
/// assert_eq!(constant_force().fz(2.0), -200.0);
/// ```
pub fn constant_force() -> ForceProfile {
    ForceProfile::Constant {
        magnitude: THESIS_FORCE,
        switch_time: THESIS_FORCE_SWITCH_TIME,
    }
}

/// The thesis's variable case: 0 N for `t < 2 s`, then `-200 - 200 sin(10 t / T)` N.
///
/// It spans [-400, 0] N and touches 0 N once, at `t = 3 pi / 2 s` (about 4.71 s).
///
/// ```
/// use armdyn::robots::scara::thesis::{constant_force, variable_force};
/// let f = variable_force();
/// assert!(f.fz(1.5 * std::f64::consts::PI).abs() < 1e-12);
/// assert!((f.fz(2.0) - (-200.0 - 200.0 * 2.0_f64.sin())).abs() < 1e-12);
/// ```
pub fn variable_force() -> ForceProfile {
    ForceProfile::Variable {
        magnitude: THESIS_FORCE,
        amplitude: THESIS_FORCE,
        omega: 10.0 / THESIS_DURATION,
        switch_time: THESIS_FORCE_SWITCH_TIME,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thesis_profiles_follow_appendix_b3() {
        let constant = ForceProfile::constant(-200.0, 2.0);
        let variable = variable_force();
        for k in 0..2000 {
            let t = k as f64 * 0.005;
            let j = t / 10.0;
            let (c, v) = if j < 0.2 {
                (0.0, 0.0)
            } else {
                (-200.0, -200.0 - 200.0 * libm::sin(j * 10.0))
            };
            assert_eq!(constant.fz(t), c, "t = {t}");
            assert!((variable.fz(t) - v).abs() < 1e-12, "t = {t}");
            assert_eq!(variable.wrench(t)[2], variable.fz(t));
        }
    }

    #[test]
    fn variable_profile_stays_between_minus_400_and_0() {
        let variable = variable_force();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for k in 400..=2000 {
            let f = variable.fz(k as f64 * 0.005);
            lo = lo.min(f);
            hi = hi.max(f);
        }
        assert!(lo >= -400.0 && hi <= 0.0);
        assert!(hi > -1e-3 && lo < -399.9);
    }

    /// Checks velocity and acceleration against central differences of `at()` at `t`,
    /// staying away from `[a, b]` around a known kink.
    fn check_derivatives<R: CartesianTrajectory>(reference: &R, avoid: Option<f64>) {
        let h = 1e-4;
        let n = 997; // not a divisor of the period: samples fall at irregular phases
        for k in 1..n {
            let t = reference.duration() * k as f64 / n as f64;
            if let Some(kink) = avoid {
                if (t - kink).abs() < 3.0 * h {
                    continue;
                }
            }
            let (m, c, p) = (reference.at(t - h), reference.at(t), reference.at(t + h));
            let v_fd = (p.position - m.position) / (2.0 * h);
            let a_fd = (p.position - 2.0 * c.position + m.position) / (h * h);
            let v_err = (v_fd - c.velocity).norm();
            let a_err = (a_fd - c.acceleration).norm();
            // Truncation O(h^2) times the third/fourth derivative, plus round-off
            // (eps / h for v, eps / h^2 for a).
            assert!(v_err < 1e-7, "t = {t}: velocity {} vs {v_fd}", c.velocity);
            assert!(
                a_err < 1e-5,
                "t = {t}: acceleration {} vs {a_fd}",
                c.acceleration
            );
            assert_eq!(
                (
                    c.yaw(),
                    c.angular_velocity,
                    c.angular_acceleration,
                    p.yaw() - m.yaw()
                ),
                (
                    0.0,
                    nalgebra::Vector3::zeros(),
                    nalgebra::Vector3::zeros(),
                    0.0
                )
            );
        }
    }

    #[test]
    fn position_test_derivatives_match_differences() {
        check_derivatives(&PositionTest::new(), None);
    }

    #[test]
    fn contact_test_derivatives_match_differences() {
        let reference = ContactTest::thesis();
        check_derivatives(&reference, Some(reference.switch_time()));
        check_derivatives(&ContactTest::new(0.1), Some(2.0));
    }

    #[test]
    fn three_zone_derivatives_match_differences() {
        check_derivatives(&ThreeZone::new(), None);
    }

    #[test]
    fn position_test_matches_eq_4_16() {
        let t = 3.7;
        let j = t / 10.0;
        let r = PositionTest::new().at(t);
        let x = 0.8 - 0.4 * j - 0.05 * libm::sin(j * 4.0 * PI);
        let y = -0.2 * j + 0.15 * libm::sin(j * 1.5 * PI);
        let z = 0.25 - 0.1 * j - 0.005 * libm::sin(j * 15.0 * PI);
        assert!((r.position - Vector3::new(x, y, z)).norm() < 1e-15);
        let start = PositionTest::new().at(0.0).position;
        assert_eq!(start, Vector3::new(0.8, 0.0, 0.25));
    }

    #[test]
    fn contact_test_is_continuous_and_jumps_in_velocity_at_the_surface() {
        let reference = ContactTest::thesis();
        let before = reference.at(2.0 - 1e-9);
        let at = reference.at(2.0);
        assert!((before.position - at.position).norm() < 1e-9);
        assert!((at.position - Vector3::new(0.5, -0.3, 0.13)).norm() < 1e-15);
        // Approach: (-1.5, -1.5, -0.6) / T; on the surface: (0, 0.75, -0.025 * 10 pi) / T.
        assert!((before.velocity - Vector3::new(-0.15, -0.15, -0.06)).norm() < 1e-12);
        let expected = Vector3::new(0.0, 0.075, -0.025 * PI);
        assert!((at.velocity - expected).norm() < 1e-12);
        // End of the run: j = 1, z = z_rs - 0.025 sin(8 pi) = z_rs.
        let end = reference.at(10.0);
        assert!((end.position - Vector3::new(0.5, 0.3, 0.13)).norm() < 1e-12);
    }

    #[test]
    fn three_zone_matches_appendix_b2() {
        let r = ThreeZone::new();
        assert_eq!(r.at(0.0).position, Vector3::new(0.25, -0.4, 0.05));
        assert!((r.at(10.0).position - Vector3::new(0.25, 0.4, 0.2)).norm() < 1e-12);
    }

    #[test]
    fn times_are_clamped() {
        let r = PositionTest::new();
        assert_eq!(r.at(-1.0), r.at(0.0));
        assert_eq!(r.at(11.0), r.at(10.0));
        assert!(r.at(f64::NAN).position.x.is_nan());
    }
}
