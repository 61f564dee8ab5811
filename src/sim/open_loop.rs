//! Open-loop simulation from a torque history, reported at the history's own sample times.

use super::rk4::rk4_step;
use super::{EndStops, SimError};
use crate::model::{forward_dynamics, JointVector, RobotModel};

/// Number of RK4 steps [`simulate_torques`] takes for `times` and `max_step`, known before
/// it starts (to refuse or announce a long run): every interval `[times[k], times[k + 1]]`
/// takes `ceil(span / max_step)` steps, at least one. Saturates at `u64::MAX`; 0 for fewer
/// than two times or a `max_step` that is not finite and positive.
///
/// ```
/// use armdyn::sim::open_loop::plant_steps;
/// assert_eq!(plant_steps(&[0.0, 1.0, 1.0005], 1e-3), 1001);
/// assert_eq!(plant_steps(&[0.0, 1e9], 1e-3), 1_000_000_000_000);
/// ```
#[must_use]
pub fn plant_steps(times: &[f64], max_step: f64) -> u64 {
    if !(max_step.is_finite() && max_step > 0.0) {
        return 0;
    }
    let total: f64 = times
        .windows(2)
        .map(|w| interval_steps(w[1] - w[0], max_step))
        .sum();
    // `as` saturates: NaN -> 0, beyond the range -> u64::MAX.
    total as u64
}

/// RK4 steps for one interval of `span` seconds.
fn interval_steps(span: f64, max_step: f64) -> f64 {
    libm::ceil(span / max_step - 1e-9).max(1.0)
}

/// Integrates the free robot (no contact) from `(q0, qd0)` at `times[0]` with `torques[k]`
/// held on `[times[k], times[k + 1])` (zero-order hold), by RK4 steps of at most `max_step`
/// seconds that divide each interval evenly; `observer(t, q, qd)` is called at every
/// `times[k]`, `progress(t)` after every RK4 step (`t` the time reached, for a caller that
/// reports on a long run). Torques are applied as given (no saturation); with `end_stops`
/// (`None`: none) a torque that pushes a joint into its limit stops it there.
///
/// # Errors
///
/// [`SimError::Config`] for mismatched or non-increasing inputs or a bad step;
/// [`SimError::NonFinite`] / [`SimError::Model`] if the state breaks down.
#[allow(clippy::too_many_arguments)]
pub fn simulate_torques<const N: usize, R: RobotModel<N>>(
    robot: &R,
    times: &[f64],
    torques: &[JointVector<N>],
    q0: &JointVector<N>,
    qd0: &JointVector<N>,
    max_step: f64,
    end_stops: Option<&EndStops<N>>,
    mut observer: impl FnMut(f64, &JointVector<N>, &JointVector<N>),
    mut progress: impl FnMut(f64),
) -> Result<(), SimError> {
    if times.is_empty() || times.len() != torques.len() {
        return Err(SimError::Config(
            "need as many torque rows as times, at least one",
        ));
    }
    if !(max_step.is_finite() && max_step > 0.0) {
        return Err(SimError::Config(
            "the integration step must be finite and > 0 s",
        ));
    }
    if times
        .windows(2)
        .any(|w| w[1].is_nan() || w[0].is_nan() || w[1] <= w[0])
        || times.iter().any(|t| !t.is_finite())
    {
        return Err(SimError::Config(
            "times must be finite and strictly increasing",
        ));
    }
    let (mut q, mut qd) = (*q0, *qd0);
    super::check_state(times[0], &q, &qd)?;
    observer(times[0], &q, &qd);
    for k in 0..times.len() - 1 {
        let span = times[k + 1] - times[k];
        let steps = interval_steps(span, max_step);
        let h = span / steps;
        for s in 0..steps as usize {
            let t = times[k] + s as f64 * h;
            let (qn, qdn) = rk4_step(&q, &qd, h, |q, qd| {
                let tau_ext = end_stops.map_or_else(JointVector::zeros, |e| -e.torque(q, qd));
                forward_dynamics(robot, q, qd, &torques[k], &tau_ext)
            })
            .map_err(|e| super::step_error(t, &q, &qd, e))?;
            q = qn;
            qd = qdn;
            super::check_state(t + h, &q, &qd)?;
            progress(t + h);
        }
        observer(times[k + 1], &q, &qd);
    }
    Ok(())
}
