//! What the actuators allow a force step along the contact normal: the largest pure push the
//! effort limits give along it, the weight along it, and the earliest settling a bang-bang
//! push allows, a physical bound no choice of gains can beat.

use nalgebra::Vector3;

use super::loop_model::DirectionalMass;
use super::DesignError;
use crate::model::{JointVector, RobotModel};

/// The tool's push along a direction `d` at one pose, as the 1-D loop model sees it:
/// `m x'' = u + w - k x`, `|u| <= max_force_n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PushLimit {
    /// The largest force along `d` with no force or moment in the other task directions:
    /// `min_i L_i / |c_i|`, `c = J_v^T d` the joint torques per newton along `d`, `L` the
    /// effort limits (N).
    pub max_force_n: f64,
    /// Gravity's force along `d` (N, positive when it helps the push): `-m c^T M^-1 g(q)`.
    pub gravity_n: f64,
    /// The apparent mass along `d`, `1 / (c^T M^-1 c)` (kg), as
    /// [`apparent_mass`](super::apparent_mass).
    pub mass_kg: f64,
}

/// The [`PushLimit`] of `robot` at `q` along the unit direction `d` (base frame), from its
/// Jacobian, mass matrix, gravity and `RobotModel::EFFORT_LIMITS`.
///
/// # Errors
///
/// [`DesignError::Model`] if the mass matrix is not positive definite or the tool cannot
/// move along `d` at this pose.
pub fn push_limit<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    d: &Vector3<f64>,
) -> Result<PushLimit, DesignError> {
    let DirectionalMass {
        c,
        m_inv_c,
        mass_kg,
    } = DirectionalMass::new(robot, q, d)?;
    // Joints whose torque a push along d does not load (|c_i| at rounding level) set no limit.
    let scale = c.amax();
    let max_force_n = (0..N)
        .filter(|&i| c[i].abs() > 1e-12 * scale)
        .map(|i| R::EFFORT_LIMITS[i] / c[i].abs())
        .fold(f64::INFINITY, f64::min);
    Ok(PushLimit {
        max_force_n,
        gravity_n: -mass_kg * m_inv_c.dot(&robot.gravity(q)),
        mass_kg,
    })
}

/// The earliest time (s) after the touch at which a step of `target_n` N into a contact of
/// `stiffness` N/m can be inside its 5 % band, with at most 2 % overshoot, for the push of
/// `limit` starting at `v0` m/s along it: full force, then full brake (bang-bang), the switch
/// instant searched on a 0.1 ms grid, the motion integrated at 10 µs (semi-implicit Euler).
/// `None` if no switch within 0.2 s stops the push inside the band within 1 s.
#[must_use]
pub fn bang_bang_settling(
    limit: &PushLimit,
    stiffness: f64,
    v0: f64,
    target_n: f64,
) -> Option<f64> {
    let (band, ceiling) = (0.95 * target_n / stiffness, 1.02 * target_n / stiffness);
    let PushLimit {
        max_force_n: u_max,
        gravity_n: w,
        mass_kg: m,
    } = *limit;
    let arrival = |switch: f64| {
        let (mut x, mut v, mut t, dt) = (0.0f64, v0, 0.0f64, 1e-5);
        let mut reached = None;
        loop {
            let u = if t < switch { u_max } else { -u_max };
            v += (u + w - stiffness * x) / m * dt;
            x += v * dt;
            t += dt;
            if reached.is_none() && x >= band {
                reached = Some(t);
            }
            if (t > switch && v <= 0.0) || t > 1.0 {
                return reached.filter(|_| x <= ceiling);
            }
        }
    };
    (1..2000)
        .filter_map(|i| arrival(f64::from(i) * 1e-4))
        .reduce(f64::min)
}
