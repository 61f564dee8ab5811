//! Coulomb friction, regularised near zero sliding speed.

use nalgebra::Vector3;

/// Below this tangential sliding speed (m/s) Coulomb friction is regularised: its magnitude
/// is `mu f_n |v_t| / FRICTION_REGULARISATION_SPEED` instead of `mu f_n` (viscous near zero
/// speed, so the force is continuous and the plant's RK4 step at 1 ms stays stable: the
/// slope `mu f_n / v_eps` on the tool's few kilograms keeps `lambda h` below 1 for 200 N and
/// `mu = 0.2`).
pub const FRICTION_REGULARISATION_SPEED: f64 = 0.01;

/// The friction force resisting a slide at tangential velocity `v_t` (m/s) under normal force
/// `f_n` (N, >= 0) with coefficient `mu`, along `v_t`:
/// `mu f_n v_t / max(|v_t|, FRICTION_REGULARISATION_SPEED)` (N).
///
/// ```
/// use armdyn::surface::sliding_friction;
/// use nalgebra::Vector3;
/// // Sliding at 0.1 m/s along x under 200 N with mu = 0.2: 40 N along x.
/// let f = sliding_friction(0.2, 200.0, &Vector3::new(0.1, 0.0, 0.0));
/// assert!((f.x - 40.0).abs() < 1e-12 && f.y == 0.0);
/// // At 1 mm/s it is regularised: a tenth of that.
/// let slow = sliding_friction(0.2, 200.0, &Vector3::new(0.001, 0.0, 0.0));
/// assert!((slow.x - 4.0).abs() < 1e-12);
/// ```
#[must_use]
pub fn sliding_friction(mu: f64, f_n: f64, v_t: &Vector3<f64>) -> Vector3<f64> {
    let speed = libm::sqrt(v_t.dot(v_t)).max(FRICTION_REGULARISATION_SPEED);
    v_t * (mu * f_n / speed)
}
