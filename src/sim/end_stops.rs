//! Joint end stops in the plant: each joint's position limits from the robot description,
//! enforced by a stiff, damped spring that acts only past the limit and never pulls.

use crate::model::{JointVector, RobotModel};

/// Natural frequency of every end stop on its joint's own inertia, rad/s (50 Hz: stiff
/// against any actuator, yet `omega h = 0.31` for the plant's 1 ms RK4 step).
pub const END_STOP_OMEGA: f64 = 2.0 * core::f64::consts::PI * 50.0;
/// Damping ratio of every end stop (critically damped: no bounce).
pub const END_STOP_DAMPING_RATIO: f64 = 1.0;

/// Stiff, damped end stops at each joint's limits.
///
/// Past a limit by `delta` (rad or m), joint `i` feels
/// `tau_i = -(k_i delta + c_i qd_i)` pushing it back (clamped so that it never pulls the
/// joint toward the limit), with `k_i = m_i omega^2`, `c_i = 2 zeta m_i omega` and `m_i` the
/// mass-matrix diagonal at the middle of the joint ranges; `omega = END_STOP_OMEGA`,
/// `zeta = END_STOP_DAMPING_RATIO`. For the SCARA's d3 this is `k = 4.9e5 N/m`: its
/// 1,000 N actuator can push it 2 mm past a limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EndStops<const N: usize> {
    lower: JointVector<N>,
    upper: JointVector<N>,
    stiffness: JointVector<N>,
    damping: JointVector<N>,
}

impl<const N: usize> EndStops<N> {
    /// End stops at `robot`'s limits, tuned as the type's docs say.
    #[must_use]
    pub fn from_model<R: RobotModel<N>>(robot: &R) -> Self {
        let lower = robot.lower_limits();
        let upper = robot.upper_limits();
        let m = robot.mass_matrix(&robot.middle_of_limits()).diagonal();
        Self {
            lower,
            upper,
            stiffness: m * (END_STOP_OMEGA * END_STOP_OMEGA),
            damping: m * (2.0 * END_STOP_DAMPING_RATIO * END_STOP_OMEGA),
        }
    }

    /// Stiffness per joint, N m/rad or N/m.
    #[must_use]
    pub fn stiffness(&self) -> &JointVector<N> {
        &self.stiffness
    }

    /// Whether joint `i` is past one of its limits at `q`.
    #[must_use]
    pub fn engaged(&self, q: &JointVector<N>, i: usize) -> bool {
        q[i] > self.upper[i] || q[i] < self.lower[i]
    }

    /// The joint torques of the stops at `(q, qd)` (zero inside the limits).
    #[must_use]
    pub fn torque(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| {
            if q[i] > self.upper[i] {
                (-(self.stiffness[i] * (q[i] - self.upper[i]) + self.damping[i] * qd[i])).min(0.0)
            } else if q[i] < self.lower[i] {
                (self.stiffness[i] * (self.lower[i] - q[i]) - self.damping[i] * qd[i]).max(0.0)
            } else {
                0.0
            }
        })
    }
}
