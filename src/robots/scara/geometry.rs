//! The SCARA's geometry: closed-form forward and inverse kinematics (thesis Section 3.1.4),
//! the two elbow solutions, reach and joint-limit checks. Velocities and accelerations of a
//! joint-space reference are in [`joint_target`](super::joint_target).
//!
//! # Geometry
//!
//! With `q = [q1, q2, d3, q4]` the forward kinematics (thesis eq. 3.5) are
//!
//! ```text
//! x = l1 cos q1 + l2 cos(q1 + q2)
//! y = l1 sin q1 + l2 sin(q1 + q2)
//! z = z0 - d3                  z0 = l0 - l4 (tool height at d3 = 0), eq. 3.9
//! yaw = q1 + q2 - q4           (rotation about the base z axis; the tool points down)
//! ```
//!
//! # Inverse
//!
//! With `r^2 = x^2 + y^2` (eq. 3.13–3.15, 3.20–3.23):
//!
//! ```text
//! cos q2 = (r^2 - l1^2 - l2^2) / (2 l1 l2),   q2 = +-acos(...)  (+: elbow up, -: elbow down)
//! q1 = atan2(y, x) - atan2(l2 sin q2, l1 + l2 cos q2)
//! d3 = z0 - z
//! q4 = q1 + q2 - yaw, wrapped into (-pi, pi]
//! ```
//!
//! The `atan2` form of `q1` equals the thesis's `atan2(y, x) - asin(l2 sin q2 / r)` (eq.
//! 3.20) whenever `l1 + l2 cos q2 >= 0` (always for `l1 >= l2`, as here) and stays right
//! otherwise. `q4` uses `q1 + q2 - yaw`, the solution consistent with the forward kinematics;
//! the printed eq. 3.23 (`q1 - q2 - phi`) and the thesis's code (`phi - q1 - q2`) are not
//! (`docs/thesis.md`, erratum 4). `sin q2` is computed as `sqrt((1 - cos q2)(1 + cos q2))` with
//! both factors formed from `(l1 + l2)^2 - r^2` and `r^2 - (l1 - l2)^2`, so it stays accurate
//! near the stretched and folded arm.
//!

use nalgebra::Vector3;

use core::f64::consts::PI;

use crate::model::{JointVector, RobotModel, Scara};
use crate::target::wrap_angle;

/// Radius slack of the reach test, m: a position at most this far outside the annulus
/// `|l1 - l2| <= r <= l1 + l2` is treated as on its boundary (rounding of sampled
/// references that touch the boundary, such as the thesis's, which start at `r = l1 + l2`).
pub const REACH_TOLERANCE: f64 = 1e-9;

/// Slack of the joint-limit test, rad or m: a joint at most this far past a limit is
/// accepted. The thesis's references start at `z = 0.25 m`, where `d3 = 0.35 - 0.25` is
/// the stroke's end (0.1 m) in exact arithmetic but `0.09999999999999998` in `f64`.
pub const LIMIT_TOLERANCE: f64 = 1e-9;

/// Which of the two inverse-kinematics solutions to use (thesis Sections 3.1.4 and 4.4).
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::Elbow;
/// assert_eq!(Elbow::Up.other(), Elbow::Down);
/// assert_eq!(Elbow::Down.sign(), -1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Elbow {
    /// Elbow up: `q2 > 0` (the thesis's `+acos` solution).
    Up,
    /// Elbow down: `q2 < 0` (the thesis's `-acos` solution).
    Down,
}

impl Elbow {
    /// The sign of `q2` in this configuration: `+1` (up) or `-1` (down).
    ///
    /// ```
    /// use armdyn::robots::scara::Elbow;
    /// assert_eq!(Elbow::Up.sign(), 1.0);
    /// ```
    pub fn sign(self) -> f64 {
        match self {
            Elbow::Up => 1.0,
            Elbow::Down => -1.0,
        }
    }

    /// The other configuration.
    ///
    /// ```
    /// use armdyn::robots::scara::Elbow;
    /// assert_eq!(Elbow::Down.other(), Elbow::Up);
    /// ```
    pub fn other(self) -> Elbow {
        match self {
            Elbow::Up => Elbow::Down,
            Elbow::Down => Elbow::Up,
        }
    }
}

impl core::fmt::Display for Elbow {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Elbow::Up => "elbow up (q2 > 0)",
            Elbow::Down => "elbow down (q2 < 0)",
        })
    }
}

/// Why inverse kinematics has no solution.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{Elbow, IkError, ScaraGeometry};
/// use nalgebra::Vector3;
///
/// let err = ScaraGeometry::thesis()
///     .inverse(&Vector3::new(0.9, 0.0, 0.2), 0.0, Elbow::Up)
///     .unwrap_err();
/// assert!(matches!(err, IkError::TooFar { .. }));
/// assert!(err.to_string().contains("0.9 m from the joint-1 axis"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum IkError {
    /// A coordinate or the yaw is NaN or infinite.
    #[error("position ({x}, {y}, {z}) m, yaw {yaw} rad: not finite")]
    NonFinite {
        /// x, m.
        x: f64,
        /// y, m.
        y: f64,
        /// z, m.
        z: f64,
        /// Yaw, rad.
        yaw: f64,
    },
    /// The position is farther from the joint-1 axis than the stretched arm reaches.
    #[error("position ({x}, {y}, {z}) m is out of reach: it is {radius} m from the joint-1 axis, beyond l1 + l2 = {max} m (the arm stretched)")]
    TooFar {
        /// x, m.
        x: f64,
        /// y, m.
        y: f64,
        /// z, m.
        z: f64,
        /// `sqrt(x^2 + y^2)`, m.
        radius: f64,
        /// `l1 + l2`, m.
        max: f64,
    },
    /// The position is closer to the joint-1 axis than the folded arm reaches.
    #[error("position ({x}, {y}, {z}) m is out of reach: it is {radius} m from the joint-1 axis, inside |l1 - l2| = {min} m (the arm folded)")]
    TooClose {
        /// x, m.
        x: f64,
        /// y, m.
        y: f64,
        /// z, m.
        z: f64,
        /// `sqrt(x^2 + y^2)`, m.
        radius: f64,
        /// `|l1 - l2|`, m.
        min: f64,
    },
}

/// A joint outside its limit (as found by [`ScaraGeometry::check_limits`]).
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::ScaraGeometry;
/// use nalgebra::Vector4;
///
/// let v = ScaraGeometry::thesis().check_limits(&Vector4::new(0.0, 0.5, 0.4, 0.0)).unwrap_err();
/// assert_eq!(v.joint, 2);
/// assert_eq!(v.to_string(), "d3 = 0.4 m outside [0.1, 0.35] m");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error("{name} = {value} {unit} outside [{lower}, {upper}] {unit}")]
pub struct LimitViolation {
    /// Joint index, from 0 (`q1, q2, d3, q4`).
    pub joint: usize,
    /// Joint name (`q1`, `q2`, `d3`, `q4`).
    pub name: &'static str,
    /// Unit of the joint coordinate (`rad` or `m`).
    pub unit: &'static str,
    /// The joint value, rad or m.
    pub value: f64,
    /// Lower limit, rad or m.
    pub lower: f64,
    /// Upper limit, rad or m.
    pub upper: f64,
}

/// The SCARA's kinematic dimensions and joint limits, for closed-form inverse kinematics.
///
/// - `l1`, `l2`: lengths of links 1 and 2 in the horizontal plane, m (thesis: 0.4, 0.4).
/// - `z0`: height of the tool at `d3 = 0`, `l0 - l4`, m (thesis: 0.35); the tool is at
///   `z = z0 - d3`.
/// - joint limits `[lower, upper]` for `q1, q2, d3, q4` (rad, rad, m, rad).
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{Elbow, ScaraGeometry};
/// use armdyn::model::{RobotModel, Scara};
/// use nalgebra::Vector3;
///
/// let ik = ScaraGeometry::from_model(&Scara);
/// let p = Vector3::new(0.5, -0.2, 0.15);
/// let q = ik.inverse(&p, 0.3, Elbow::Down).unwrap();
/// assert!(q[1] < 0.0);
/// let pose = Scara.end_effector_pose(&q);
/// assert!((pose.fixed_view::<3, 1>(0, 3) - p).norm() < 1e-12);
/// assert!(ik.within_limits(&q));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaraGeometry {
    l1: f64,
    l2: f64,
    z0: f64,
    limits: [[f64; 2]; 4],
}

impl ScaraGeometry {
    /// The geometry of the generated SCARA model, read from its forward kinematics at `q = 0`.
    ///
    /// At `q = 0` the arm lies along the base x axis: frame 1 (the elbow axis) is at `(l1, 0,
    /// l0)`, frame 2 at `(l1 + l2, 0, l0)` and the tool (frame 4) at `(l1 + l2, 0, l0 - l4)`.
    /// The lengths are read from these frame origins, so they follow any change of
    /// `robots/scara.toml`; the limits are [`Scara::JOINT_LIMITS`](RobotModel::JOINT_LIMITS).
    ///
    /// ```
    /// use armdyn::robots::scara::ScaraGeometry;
    /// let g = ScaraGeometry::from_model(&armdyn::model::Scara);
    /// assert!((g.l1() - 0.4).abs() < 1e-15 && (g.z0() - 0.35).abs() < 1e-15);
    /// ```
    pub fn from_model(robot: &Scara) -> Self {
        let poses = robot.frame_poses(&JointVector::<4>::zeros());
        let origin = |k: usize| Vector3::new(poses[k][(0, 3)], poses[k][(1, 3)], poses[k][(2, 3)]);
        let (elbow, wrist, tool) = (origin(0), origin(1), origin(3));
        ScaraGeometry {
            l1: crate::math::hypot(elbow.x, elbow.y),
            l2: crate::math::hypot(wrist.x - elbow.x, wrist.y - elbow.y),
            z0: tool.z,
            limits: Scara::JOINT_LIMITS,
        }
    }

    /// The thesis's numbers (Table 3.1, Appendix B.2): `l1 = l2 = 0.4 m`, `z0 = 0.5 - 0.15 =
    /// 0.35 m`, limits `q1` in `[-pi/2, pi/2]`, `q2` in `[-7pi/8, 7pi/8]`, `d3` in `[0.1,
    /// 0.35] m`, `q4` in `[-pi, pi]`. For documentation and tests; the controllers use
    /// [`ScaraGeometry::from_model`], which [`ScaraGeometry::joint_target`] assumes (it takes
    /// the Jacobian from the generated model).
    ///
    /// ```
    /// use armdyn::robots::scara::ScaraGeometry;
    /// assert_eq!(ScaraGeometry::thesis().l2(), 0.4);
    /// ```
    pub fn thesis() -> Self {
        ScaraGeometry {
            l1: 0.4,
            l2: 0.4,
            z0: 0.35,
            limits: [
                [-PI / 2.0, PI / 2.0],
                [-7.0 * PI / 8.0, 7.0 * PI / 8.0],
                [0.1, 0.35],
                [-PI, PI],
            ],
        }
    }

    /// Length of link 1 in the horizontal plane (shoulder to elbow axis), m.
    ///
    /// ```
    /// assert_eq!(armdyn::robots::scara::ScaraGeometry::thesis().l1(), 0.4);
    /// ```
    pub fn l1(&self) -> f64 {
        self.l1
    }

    /// Length of link 2 in the horizontal plane (elbow axis to tool axis), m.
    ///
    /// ```
    /// assert_eq!(armdyn::robots::scara::ScaraGeometry::thesis().l2(), 0.4);
    /// ```
    pub fn l2(&self) -> f64 {
        self.l2
    }

    /// Height of the tool at `d3 = 0`, `l0 - l4`, m; the tool is at `z = z0 - d3`.
    ///
    /// ```
    /// assert_eq!(armdyn::robots::scara::ScaraGeometry::thesis().z0(), 0.35);
    /// ```
    pub fn z0(&self) -> f64 {
        self.z0
    }

    /// Joint limits `[lower, upper]` of `q1, q2, d3, q4` (rad, rad, m, rad).
    ///
    /// ```
    /// let limits = armdyn::robots::scara::ScaraGeometry::thesis().limits();
    /// assert_eq!(limits[2], [0.1, 0.35]);
    /// ```
    pub fn limits(&self) -> [[f64; 2]; 4] {
        self.limits
    }

    /// Forward kinematics from this geometry: tool position (m) and yaw `q1 + q2 - q4` (rad)
    /// for joints `q` (thesis eq. 3.5, 3.9).
    ///
    /// ```
    /// use armdyn::robots::scara::ScaraGeometry;
    /// use nalgebra::{Vector3, Vector4};
    /// let (p, yaw) = ScaraGeometry::thesis().forward(&Vector4::new(0.0, 0.0, 0.1, 0.2));
    /// assert!((p - Vector3::new(0.8, 0.0, 0.25)).norm() < 1e-15);
    /// assert_eq!(yaw, -0.2);
    /// ```
    pub fn forward(&self, q: &JointVector<4>) -> (Vector3<f64>, f64) {
        let (q1, q12) = (q[0], q[0] + q[1]);
        let position = Vector3::new(
            self.l1 * libm::cos(q1) + self.l2 * libm::cos(q12),
            self.l1 * libm::sin(q1) + self.l2 * libm::sin(q12),
            self.z0 - q[2],
        );
        (position, q12 - q[3])
    }

    /// Closed-form inverse kinematics: the joints `[q1, q2, d3, q4]` (rad, rad, m, rad) that
    /// put the tool at `position` (m, base frame) with yaw `yaw` (rad), in the given elbow
    /// configuration (thesis eq. 3.20–3.23, with `q4 = q1 + q2 - yaw`; see the [module
    /// documentation](self)).
    ///
    /// `q1` and `q4` are wrapped into `(-pi, pi]`, `q2` is in `[-pi, pi]`. Joint limits are
    /// *not* checked here (see [`ScaraGeometry::check_limits`]): the workspace planner needs
    /// both solutions whatever their limits. With the arm exactly stretched or folded
    /// (`sin q2 = 0`) both configurations give the same joints.
    ///
    /// # Errors
    ///
    /// [`IkError::NonFinite`] for a NaN or infinite input; [`IkError::TooFar`] /
    /// [`IkError::TooClose`] if the distance from the joint-1 axis is outside `[|l1 - l2|,
    /// l1 + l2]` by more than [`REACH_TOLERANCE`].
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ScaraGeometry};
    /// use nalgebra::Vector3;
    ///
    /// let ik = ScaraGeometry::thesis();
    /// let p = Vector3::new(0.4, 0.4, 0.2); // q1 = 0, q2 = +-pi/2 ... or q1 = pi/2, q2 = -pi/2
    /// let up = ik.inverse(&p, 0.0, Elbow::Up).unwrap();
    /// let down = ik.inverse(&p, 0.0, Elbow::Down).unwrap();
    /// assert!((up[0] - 0.0).abs() < 1e-12 && (up[1] - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    /// assert!((down[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    /// assert!((up[2] - 0.15).abs() < 1e-15);
    /// ```
    pub fn inverse(
        &self,
        position: &Vector3<f64>,
        yaw: f64,
        elbow: Elbow,
    ) -> Result<JointVector<4>, IkError> {
        let (x, y, z) = (position.x, position.y, position.z);
        if !(x.is_finite() && y.is_finite() && z.is_finite() && yaw.is_finite()) {
            return Err(IkError::NonFinite { x, y, z, yaw });
        }
        let (l1, l2) = (self.l1, self.l2);
        let radius = crate::math::hypot(x, y);
        let (outer, inner) = (l1 + l2, libm::fabs(l1 - l2));
        if radius > outer + REACH_TOLERANCE {
            return Err(IkError::TooFar {
                x,
                y,
                z,
                radius,
                max: outer,
            });
        }
        if radius < inner - REACH_TOLERANCE {
            return Err(IkError::TooClose {
                x,
                y,
                z,
                radius,
                min: inner,
            });
        }
        let two_l1l2 = 2.0 * l1 * l2;
        // 1 - cos q2 and 1 + cos q2, each from a difference of squares that vanishes exactly
        // on its own boundary; clamped at 0 within the reach tolerance.
        let one_minus_c2 = ((outer - radius) * (outer + radius) / two_l1l2).max(0.0);
        let one_plus_c2 = ((radius - inner) * (radius + inner) / two_l1l2).max(0.0);
        let c2 = 0.5 * (one_plus_c2 - one_minus_c2);
        let s2 = elbow.sign() * crate::math::sqrt(one_minus_c2 * one_plus_c2);
        let q2 = libm::atan2(s2, c2);
        let q1 = wrap_angle(libm::atan2(y, x) - libm::atan2(l2 * s2, l1 + l2 * c2));
        let d3 = self.z0 - z;
        let q4 = wrap_angle(q1 + q2 - yaw);
        Ok(JointVector::<4>::new(q1, q2, d3, q4))
    }

    /// Checks `q` against the joint limits (inclusive, with a slack of [`LIMIT_TOLERANCE`]);
    /// the first joint outside its range is reported.
    ///
    /// # Errors
    ///
    /// [`LimitViolation`] naming the first joint (in the order `q1, q2, d3, q4`) outside its
    /// limits; NaN is outside.
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::robots::scara::ScaraGeometry;
    /// use nalgebra::Vector4;
    /// let g = ScaraGeometry::thesis();
    /// assert!(g.check_limits(&Vector4::new(0.0, 0.5, 0.2, 0.0)).is_ok());
    /// let v = g.check_limits(&Vector4::new(2.0, 0.5, 0.2, 0.0)).unwrap_err();
    /// assert_eq!((v.joint, v.name), (0, "q1"));
    /// ```
    pub fn check_limits(&self, q: &JointVector<4>) -> Result<(), LimitViolation> {
        for (joint, &[lower, upper]) in self.limits.iter().enumerate() {
            let value = q[joint];
            if !(lower - LIMIT_TOLERANCE <= value && value <= upper + LIMIT_TOLERANCE) {
                return Err(LimitViolation {
                    joint,
                    name: Scara::JOINT_NAMES[joint],
                    unit: Scara::JOINT_KINDS[joint].position_unit(),
                    value,
                    lower,
                    upper,
                });
            }
        }
        Ok(())
    }

    /// Whether every joint of `q` is within its limits (see [`ScaraGeometry::check_limits`]).
    ///
    /// ```
    /// use armdyn::robots::scara::ScaraGeometry;
    /// use nalgebra::Vector4;
    /// assert!(!ScaraGeometry::thesis().within_limits(&Vector4::new(0.0, 3.0, 0.2, 0.0)));
    /// ```
    pub fn within_limits(&self, q: &JointVector<4>) -> bool {
        self.check_limits(q).is_ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ik() -> ScaraGeometry {
        ScaraGeometry::from_model(&Scara)
    }

    #[test]
    fn geometry_from_the_model_matches_the_thesis() {
        let (g, t) = (ik(), ScaraGeometry::thesis());
        assert!((g.l1 - t.l1).abs() < 1e-15);
        assert!((g.l2 - t.l2).abs() < 1e-15);
        assert!((g.z0 - t.z0).abs() < 1e-15);
        for (a, b) in g.limits.iter().zip(t.limits.iter()) {
            assert!((a[0] - b[0]).abs() < 1e-15 && (a[1] - b[1]).abs() < 1e-15);
        }
    }

    #[test]
    fn geometric_forward_kinematics_matches_the_generated_one() {
        let g = ik();
        for k in 0..50 {
            let f = k as f64;
            let q = JointVector::<4>::new(
                libm::sin(1.3 * f) * 1.5,
                libm::cos(0.7 * f) * 2.5,
                0.1 + 0.25 * (0.5 + 0.5 * libm::sin(f)),
                libm::sin(2.1 * f) * 3.0,
            );
            let pose = Scara.end_effector_pose(&q);
            let (p, yaw) = g.forward(&q);
            assert!((pose.fixed_view::<3, 1>(0, 3) - p).norm() < 1e-14);
            let yaw_generated = libm::atan2(pose[(1, 0)], pose[(0, 0)]);
            assert!(wrap_angle(yaw - yaw_generated).abs() < 1e-14);
        }
    }

    #[test]
    fn elbows_give_the_sign_of_q2() {
        let p = Vector3::new(0.5, 0.2, 0.1);
        assert!(ik().inverse(&p, 0.0, Elbow::Up).unwrap()[1] > 0.0);
        assert!(ik().inverse(&p, 0.0, Elbow::Down).unwrap()[1] < 0.0);
    }

    #[test]
    fn q4_follows_erratum_4() {
        let p = Vector3::new(0.3, 0.5, 0.2);
        let q = ik().inverse(&p, 0.4, Elbow::Up).unwrap();
        assert!((wrap_angle(q[0] + q[1] - q[3]) - 0.4).abs() < 1e-14);
        assert!(q[3] > -PI && q[3] <= PI);
    }

    #[test]
    fn unreachable_positions_are_named() {
        let err = ik()
            .inverse(&Vector3::new(0.0, 0.85, 0.1), 0.0, Elbow::Up)
            .unwrap_err();
        let text = err.to_string();
        assert!(text.contains("(0, 0.85, 0.1) m"), "{text}");
        assert!(text.contains("beyond l1 + l2 = 0.8"), "{text}");
        assert!(matches!(
            ik().inverse(&Vector3::new(f64::NAN, 0.0, 0.0), 0.0, Elbow::Up),
            Err(IkError::NonFinite { .. })
        ));
        // Within the tolerance of the boundary: accepted, stretched.
        let q = ik()
            .inverse(&Vector3::new(0.8 + 1e-12, 0.0, 0.1), 0.0, Elbow::Down)
            .unwrap();
        assert_eq!(q[1], 0.0);
    }

    #[test]
    fn too_close_only_exists_for_unequal_links() {
        let g = ScaraGeometry {
            l1: 0.5,
            l2: 0.3,
            ..ScaraGeometry::thesis()
        };
        let err = g
            .inverse(&Vector3::new(0.1, 0.0, 0.0), 0.0, Elbow::Up)
            .unwrap_err();
        assert!(matches!(err, IkError::TooClose { min, .. } if (min - 0.2).abs() < 1e-15));
        // The base axis itself is reachable with l1 = l2: the arm folded, q2 = +-pi.
        let q = ik()
            .inverse(&Vector3::new(0.0, 0.0, 0.1), 0.0, Elbow::Up)
            .unwrap();
        assert!((q[1] - PI).abs() < 1e-15 && q.iter().all(|v| v.is_finite()));
    }

    #[test]
    fn wrap_angle_range() {
        for k in -40..=40 {
            let a = 0.37 * k as f64;
            let w = wrap_angle(a);
            assert!(w > -PI && w <= PI);
            assert!(libm::fabs(libm::remainder(a - w, 2.0 * PI)) < 1e-12);
        }
    }
}
