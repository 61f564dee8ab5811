//! Tests of `armdyn::target::orientation`: orientation errors: the short rotation whatever the
//! quaternion sign, small errors to full precision, the inverse right Jacobian, the yaw of a
//! rotation about z.

use armdyn::target::orientation::*;
use core::f64::consts::PI;
use nalgebra::{UnitQuaternion, Vector3};

#[test]
fn the_error_is_the_short_rotation_and_ignores_the_quaternion_sign() {
    let a = from_rpy(0.3, -0.2, 1.0);
    let b = UnitQuaternion::from_scaled_axis(Vector3::new(0.0, 0.0, 0.5)) * a;
    assert!((error(&b, &a) - Vector3::new(0.0, 0.0, 0.5)).norm() < 1e-15);
    let minus_b = UnitQuaternion::new_unchecked(-b.into_inner());
    assert!((error(&minus_b, &a) - Vector3::new(0.0, 0.0, 0.5)).norm() < 1e-15);
    // Past half a turn the other way round is shorter.
    let c = from_yaw(PI + 0.1);
    assert!((error(&c, &UnitQuaternion::identity()).z + (PI - 0.1)).abs() < 1e-14);
    assert_eq!(error(&a, &a), Vector3::zeros());
}

#[test]
fn tiny_errors_keep_their_digits() {
    let a = from_rpy(0.7, 0.4, -2.0);
    let d = Vector3::new(3e-12, -1e-12, 2e-12);
    let b = UnitQuaternion::from_scaled_axis(d) * a;
    assert!((error(&b, &a) - d).norm() < 1e-20 + 1e-4 * d.norm());
    // From matrices too.
    let (ma, mb) = (a.to_rotation_matrix(), b.to_rotation_matrix());
    let e = error(&of_matrix(mb.matrix()), &of_matrix(ma.matrix()));
    assert!((e - d).norm() < 1e-15, "{e}");
}

#[test]
fn the_inverse_right_jacobian_predicts_the_error_change() {
    let d = from_rpy(0.4, -0.3, 1.1);
    let a = from_rpy(-0.2, 0.5, -0.7);
    let e = error(&d, &a);
    let dw = Vector3::new(1e-7, -2e-7, 0.5e-7);
    let turned = UnitQuaternion::from_scaled_axis(dw) * a;
    let predicted = e - right_jacobian_inverse(&e) * dw;
    assert!((error(&d, &turned) - predicted).norm() < 1e-13);
}

#[test]
fn yaw_of_a_rotation_about_z_is_its_angle() {
    for y in [-3.0, -1.0, 0.0, 0.5, 3.1] {
        assert!((yaw(&from_yaw(y)) - y).abs() < 1e-15);
        assert!(from_yaw(y).angle_to(&from_rpy(0.0, 0.0, y)) < 1e-15);
        assert!(from_yaw(y).angle_to(&UnitQuaternion::from_euler_angles(0.0, 0.0, y)) < 1e-15);
    }
}
