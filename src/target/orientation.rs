//! Orientation helpers: the SO(3) logarithm as the orientation error and the geodesic along
//! it, roll-pitch-yaw (fixed axes x-y-z, REP-103), rotations about base z, and the orientation
//! of a pose matrix.
//!
//! The error is computed on unit quaternions, whose logarithm `2 atan2(|v|, |w|)` is
//! accurate to rounding at every angle, small ones included (the trace formula
//! `acos((tr R - 1) / 2)` of a rotation matrix loses half the digits near 0).

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

/// A homogeneous transform.
type Pose = nalgebra::Matrix4<f64>;

/// The orientation error `log(R_d R^T)`: the rotation vector (unit axis times angle, angle in
/// `[0, pi]`, base frame, rad) that turns `actual` into `desired`, so that for a small error
/// `desired ~ exp([e]x) actual`. It is zero exactly when the two are equal, whatever the sign
/// of their quaternions.
///
/// ```
/// use armdyn::target::orientation::{error, from_yaw};
/// let e = error(&from_yaw(0.3), &from_yaw(0.1));
/// assert!((e.z - 0.2).abs() < 1e-15 && e.x == 0.0 && e.y == 0.0);
/// ```
#[must_use]
pub fn error(desired: &UnitQuaternion<f64>, actual: &UnitQuaternion<f64>) -> Vector3<f64> {
    log(&(desired * actual.inverse()))
}

/// `exp(s [phi]x) from`: the orientation a fraction `s` of the way along the rotation vector
/// `phi` (base frame, rad) from `from`; `from` itself, bit for bit, when `phi` is zero. With
/// `phi = error(to, from)` and `s` in `[0, 1]` it runs from `from` to `to` the short way.
///
/// ```
/// use armdyn::target::orientation::{along, error, from_yaw};
/// let (a, b) = (from_yaw(0.1), from_yaw(0.5));
/// let half = along(&a, &error(&b, &a), 0.5);
/// assert!((error(&half, &from_yaw(0.3))).norm() < 1e-15);
/// assert_eq!(along(&a, &error(&a, &a), 0.5), a);
/// ```
#[must_use]
pub fn along(from: &UnitQuaternion<f64>, phi: &Vector3<f64>, s: f64) -> UnitQuaternion<f64> {
    if *phi == Vector3::zeros() {
        *from
    } else {
        UnitQuaternion::from_scaled_axis(phi * s) * from
    }
}

/// The SO(3) logarithm of `q`: axis times angle, angle in `[0, pi]` (rad), the short way
/// round whatever the sign of the quaternion.
///
/// ```
/// use armdyn::target::orientation::log;
/// use nalgebra::{UnitQuaternion, Vector3};
/// let v = Vector3::new(0.1, -0.2, 0.3);
/// assert!((log(&UnitQuaternion::from_scaled_axis(v)) - v).norm() < 1e-15);
/// ```
#[must_use]
pub fn log(q: &UnitQuaternion<f64>) -> Vector3<f64> {
    let (w, v) = (q.w, q.imag());
    // The sign that makes w >= 0 picks the rotation of angle <= pi.
    let (w, v) = if w < 0.0 { (-w, -v) } else { (w, v) };
    let s = v.norm();
    if s == 0.0 {
        return Vector3::zeros();
    }
    let angle = 2.0 * libm::atan2(s, w);
    v * (angle / s)
}

/// The inverse right Jacobian of SO(3) at the rotation vector `phi` (rad):
/// `log(exp([phi]x) exp([xi]x)) = phi + J_r^-1(phi) xi + O(|xi|^2)`, so that the orientation
/// error [`error`] moves by `-J_r^-1(e) dw` when the actual orientation turns by `dw`
/// (base frame):
///
/// ```text
/// J_r^-1(phi) = I + [phi]x / 2 + (1 / theta^2 - (1 + cos theta) / (2 theta sin theta)) [phi]x^2
/// ```
///
/// (the last coefficient by its series `1/12 + theta^2/720` below 1e-4 rad).
///
/// ```
/// use armdyn::target::orientation::right_jacobian_inverse;
/// use nalgebra::{Matrix3, Vector3};
/// assert_eq!(right_jacobian_inverse(&Vector3::zeros()), Matrix3::identity());
/// ```
#[must_use]
pub fn right_jacobian_inverse(phi: &Vector3<f64>) -> Matrix3<f64> {
    let theta = phi.norm();
    let k = phi.cross_matrix();
    let c = if theta < 1e-4 {
        1.0 / 12.0 + theta * theta / 720.0
    } else {
        1.0 / (theta * theta) - (1.0 + libm::cos(theta)) / (2.0 * theta * libm::sin(theta))
    };
    Matrix3::identity() + k * 0.5 + k * k * c
}

/// The rotation `Rz(yaw)` about the base z axis (rad).
///
/// ```
/// use armdyn::target::orientation::{from_yaw, yaw};
/// assert!((yaw(&from_yaw(1.2)) - 1.2).abs() < 1e-15);
/// assert_eq!(from_yaw(0.0), nalgebra::UnitQuaternion::identity());
/// ```
#[must_use]
pub fn from_yaw(yaw: f64) -> UnitQuaternion<f64> {
    if yaw == 0.0 {
        return UnitQuaternion::identity();
    }
    let (s, c) = (libm::sin(0.5 * yaw), libm::cos(0.5 * yaw));
    UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(c, 0.0, 0.0, s))
}

/// The rotation of roll, pitch, yaw about the fixed base axes x, then y, then z (rad,
/// REP-103): `R = Rz(yaw) Ry(pitch) Rx(roll)`.
///
/// ```
/// use armdyn::target::orientation::{from_rpy, rpy};
/// let (r, p, y) = rpy(&from_rpy(0.1, -0.4, 2.0));
/// assert!((r - 0.1).abs() < 1e-14 && (p + 0.4).abs() < 1e-14 && (y - 2.0).abs() < 1e-14);
/// ```
#[must_use]
pub fn from_rpy(roll: f64, pitch: f64, yaw: f64) -> UnitQuaternion<f64> {
    if roll == 0.0 && pitch == 0.0 {
        return from_yaw(yaw);
    }
    UnitQuaternion::from_euler_angles(roll, pitch, yaw)
}

/// Roll, pitch and yaw (fixed axes x-y-z, rad) of `q`: pitch in `[-pi/2, pi/2]`, roll and
/// yaw in `(-pi, pi]`.
#[must_use]
pub fn rpy(q: &UnitQuaternion<f64>) -> (f64, f64, f64) {
    q.euler_angles()
}

/// The yaw of `q`, rad in `(-pi, pi]`: the angle about base z of its x axis projected on the
/// base x-y plane, `atan2(R10, R00)` (for a rotation about z alone, its angle).
#[must_use]
pub fn yaw(q: &UnitQuaternion<f64>) -> f64 {
    let (w, x, y, z) = (q.w, q.i, q.j, q.k);
    libm::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
}

/// The orientation of a homogeneous transform's rotation block (`pose` from forward
/// kinematics; its rotation is orthonormal to rounding).
///
/// ```
/// use armdyn::target::orientation::{from_rpy, of_pose};
/// let q = from_rpy(0.3, 0.2, -1.0);
/// let mut pose = nalgebra::Matrix4::identity();
/// pose.fixed_view_mut::<3, 3>(0, 0).copy_from(q.to_rotation_matrix().matrix());
/// assert!(q.angle_to(&of_pose(&pose)) < 1e-15);
/// ```
#[must_use]
pub fn of_pose(pose: &Pose) -> UnitQuaternion<f64> {
    of_matrix(&pose.fixed_view::<3, 3>(0, 0).into_owned())
}

/// The orientation of a rotation matrix (orthonormal to rounding), by the branch on its
/// largest diagonal combination (accurate at every angle).
#[must_use]
pub fn of_matrix(m: &Matrix3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(*m))
}
