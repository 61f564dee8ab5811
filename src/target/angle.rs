//! Angles: wrapping into one turn.

use core::f64::consts::PI;

/// `angle` wrapped into `(-pi, pi]`, rad (IEEE remainder by `2 pi`, so exact for angles
/// already in range).
///
/// ```
/// use armdyn::target::wrap_angle;
/// use std::f64::consts::PI;
/// assert!((wrap_angle(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-15);
/// assert_eq!(wrap_angle(-PI), PI);
/// assert_eq!(wrap_angle(0.25), 0.25);
/// ```
#[must_use]
pub fn wrap_angle(angle: f64) -> f64 {
    let wrapped = libm::remainder(angle, 2.0 * PI);
    if wrapped <= -PI {
        wrapped + 2.0 * PI
    } else {
        wrapped
    }
}
