//! One fixed step of the classical fourth-order Runge–Kutta method for `q'' = f(q, q')`.

use crate::model::JointVector;

/// Advances `(q, qd)` by `h` seconds with RK4, `qdd = accel(q, qd)`; returns the new state.
///
/// # Errors
///
/// Whatever `accel` returns.
///
/// ```
/// use armdyn::sim::rk4::rk4_step;
/// use nalgebra::Vector1;
/// // Harmonic oscillator q'' = -q from q = 1: q(0.1) = cos 0.1 to O(h^5).
/// let (q, _) = rk4_step(&Vector1::new(1.0), &Vector1::new(0.0), 0.1, |q, _| Ok::<_, ()>(-q)).unwrap();
/// assert!((q[0] - 0.1f64.cos()).abs() < 1e-7);
/// ```
pub fn rk4_step<const N: usize, E>(
    q: &JointVector<N>,
    qd: &JointVector<N>,
    h: f64,
    mut accel: impl FnMut(&JointVector<N>, &JointVector<N>) -> Result<JointVector<N>, E>,
) -> Result<(JointVector<N>, JointVector<N>), E> {
    let k1v = *qd;
    let k1a = accel(q, qd)?;
    let q2 = q + k1v * (h / 2.0);
    let v2 = qd + k1a * (h / 2.0);
    let k2a = accel(&q2, &v2)?;
    let q3 = q + v2 * (h / 2.0);
    let v3 = qd + k2a * (h / 2.0);
    let k3a = accel(&q3, &v3)?;
    let q4 = q + v3 * h;
    let v4 = qd + k3a * h;
    let k4a = accel(&q4, &v4)?;
    let q_next = q + (k1v + v2 * 2.0 + v3 * 2.0 + v4) * (h / 6.0);
    let qd_next = qd + (k1a + k2a * 2.0 + k3a * 2.0 + k4a) * (h / 6.0);
    Ok((q_next, qd_next))
}
