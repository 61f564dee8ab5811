//! Open-loop simulation from a torque history, reported at the history's own sample times.

use super::rk4::rk4_step;
use super::{EndStops, SimError};
use crate::model::{forward_dynamics, JointVector, RobotModel};

/// Integrates the free robot (no contact) from `(q0, qd0)` at `times[0]` with `torques[k]`
/// held on `[times[k], times[k + 1])` (zero-order hold), by RK4 steps of at most `max_step`
/// seconds that divide each interval evenly; `observer(t, q, qd)` is called at every
/// `times[k]`. Torques are applied as given (no saturation).
///
/// # Errors
///
/// [`SimError::Config`] for mismatched or non-increasing inputs or a bad step;
/// [`SimError::NonFinite`] / [`SimError::Model`] if the state breaks down.
pub fn simulate_torques<const N: usize, R: RobotModel<N>>(
    robot: &R,
    times: &[f64],
    torques: &[JointVector<N>],
    q0: &JointVector<N>,
    qd0: &JointVector<N>,
    max_step: f64,
    observer: impl FnMut(f64, &JointVector<N>, &JointVector<N>),
) -> Result<(), SimError> {
    simulate_torques_with_stops(robot, times, torques, q0, qd0, max_step, None, observer)
}

/// [`simulate_torques`] with joint end stops in the plant (`None`: none): a torque history
/// that pushes a joint into its limit stops it there.
///
/// # Errors
///
/// As [`simulate_torques`].
#[allow(clippy::too_many_arguments)]
pub fn simulate_torques_with_stops<const N: usize, R: RobotModel<N>>(
    robot: &R,
    times: &[f64],
    torques: &[JointVector<N>],
    q0: &JointVector<N>,
    qd0: &JointVector<N>,
    max_step: f64,
    end_stops: Option<&EndStops<N>>,
    mut observer: impl FnMut(f64, &JointVector<N>, &JointVector<N>),
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
        let steps = libm::ceil(span / max_step - 1e-9).max(1.0);
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
        }
        observer(times[k + 1], &q, &qd);
    }
    Ok(())
}
