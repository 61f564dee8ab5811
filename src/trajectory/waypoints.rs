//! A reference through waypoints (time and full pose) with a stated interpolation (feature
//! `std`): what a scenario file writes when no thesis reference fits.
//!
//! Between two waypoints `a` and `b` the position moves along the straight segment and the
//! orientation along the geodesic of SO(3) (slerp, the short way round), both with the same
//! time scaling `s(u)`, `u = (t - t_a) / (t_b - t_a)`:
//!
//! ```text
//! p(t) = p_a + s (p_b - p_a)            v = s' (p_b - p_a) / T      a = s'' (p_b - p_a) / T^2
//! R(t) = exp(s [phi]x) R_a              w = s' phi / T              alpha = s'' phi / T^2
//! phi  = log(R_b R_a^T)   (base frame, angle <= pi)
//! ```

use nalgebra::Vector3;

use super::CartesianTrajectory;
use crate::target::{orientation, CartesianTarget, PoseSample};

/// How the pose moves between two waypoints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// Straight at constant velocity: velocity steps at each waypoint, acceleration is zero.
    Linear,
    /// Along the straight segment with the quintic time scaling
    /// `s = 10 u^3 - 15 u^4 + 6 u^5`: at rest at every waypoint, continuous acceleration.
    Quintic,
}

impl Interpolation {
    /// The names of the scenario format, `"linear"` and `"quintic"`.
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "linear" => Some(Self::Linear),
            "quintic" => Some(Self::Quintic),
            _ => None,
        }
    }
}

/// Why waypoints do not make a reference.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum WaypointError {
    /// Fewer than two waypoints.
    #[error("need at least 2 waypoints, got {0}")]
    TooFew(usize),
    /// A value is not finite.
    #[error("waypoint {0}: values must be finite")]
    NonFinite(usize),
    /// The first time is negative.
    #[error("waypoint 0: time {0} s is negative")]
    NegativeStart(f64),
    /// Times do not increase strictly.
    #[error("waypoint {index}: time {t} s is not after the previous one ({previous} s)")]
    NotIncreasing {
        /// Index of the waypoint.
        index: usize,
        /// Its time, s.
        t: f64,
        /// The previous time, s.
        previous: f64,
    },
}

/// Waypoints and their interpolation; before the first time the first pose is held, after
/// the last the last.
///
/// ```
/// use armdyn::trajectory::waypoints::{Interpolation, Waypoints};
/// use armdyn::trajectory::CartesianTrajectory;
/// use armdyn::target::PoseSample;
/// use nalgebra::Vector3;
/// let w = Waypoints::new(
///     &[
///         PoseSample::with_yaw(0.0, Vector3::new(0.5, 0.0, 0.2), 0.0),
///         PoseSample::with_yaw(2.0, Vector3::new(0.5, 0.2, 0.2), 0.4),
///     ],
///     Interpolation::Quintic,
/// )
/// .unwrap();
/// let mid = w.at(1.0);
/// assert!((mid.position.y - 0.1).abs() < 1e-15);
/// assert!((mid.velocity.y - 0.1875).abs() < 1e-12); // 15/8 of the mean 0.1 m/s
/// assert_eq!(w.at(2.0).velocity, Vector3::zeros());
/// assert!((w.at(1.0).yaw() - 0.2).abs() < 1e-15); // half way round, too
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Waypoints {
    points: Vec<PoseSample>,
    interpolation: Interpolation,
}

impl Waypoints {
    /// A reference through `points` (strictly increasing times from 0 or later).
    ///
    /// # Errors
    ///
    /// [`WaypointError`] naming the waypoint at fault.
    pub fn new(points: &[PoseSample], interpolation: Interpolation) -> Result<Self, WaypointError> {
        if points.len() < 2 {
            return Err(WaypointError::TooFew(points.len()));
        }
        for (i, p) in points.iter().enumerate() {
            let q = p.orientation.quaternion();
            let finite = [
                p.t,
                p.position.x,
                p.position.y,
                p.position.z,
                q.w,
                q.i,
                q.j,
                q.k,
            ]
            .iter()
            .all(|v| v.is_finite());
            if !finite {
                return Err(WaypointError::NonFinite(i));
            }
            if i == 0 && p.t < 0.0 {
                return Err(WaypointError::NegativeStart(p.t));
            }
            if i > 0 && p.t <= points[i - 1].t {
                return Err(WaypointError::NotIncreasing {
                    index: i,
                    t: p.t,
                    previous: points[i - 1].t,
                });
            }
        }
        Ok(Self {
            points: points.to_vec(),
            interpolation,
        })
    }

    /// The interpolation.
    #[must_use]
    pub fn interpolation(&self) -> Interpolation {
        self.interpolation
    }
}

/// Time scaling on `u in [0, 1]`: `(s, ds/du, d2s/du2)`.
fn scaling(kind: Interpolation, u: f64) -> (f64, f64, f64) {
    match kind {
        Interpolation::Linear => (u, 1.0, 0.0),
        Interpolation::Quintic => {
            let (u2, u3) = (u * u, u * u * u);
            (
                u3 * (10.0 - 15.0 * u + 6.0 * u2),
                30.0 * u2 * (1.0 - 2.0 * u + u2),
                60.0 * u * (1.0 - 3.0 * u + 2.0 * u2),
            )
        }
    }
}

impl CartesianTrajectory for Waypoints {
    fn duration(&self) -> f64 {
        self.points[self.points.len() - 1].t
    }

    fn at(&self, t: f64) -> CartesianTarget {
        let first = &self.points[0];
        let last = &self.points[self.points.len() - 1];
        if t <= first.t {
            return CartesianTarget::at_rest(first.position, first.orientation);
        }
        if t >= last.t {
            return CartesianTarget::at_rest(last.position, last.orientation);
        }
        let k = self.points.partition_point(|p| p.t <= t) - 1;
        let (a, b) = (&self.points[k], &self.points[k + 1]);
        let span = b.t - a.t;
        let (s, ds, dds) = scaling(self.interpolation, (t - a.t) / span);
        let dp: Vector3<f64> = b.position - a.position;
        let phi = orientation::error(&b.orientation, &a.orientation);
        let orientation = orientation::along(&a.orientation, &phi, s);
        CartesianTarget {
            position: a.position + dp * s,
            orientation,
            velocity: dp * (ds / span),
            angular_velocity: phi * (ds / span),
            acceleration: dp * (dds / (span * span)),
            angular_acceleration: phi * (dds / (span * span)),
        }
    }
}
