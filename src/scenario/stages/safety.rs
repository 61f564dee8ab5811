//! Stage 6: the safety supervisor around the controller (inside the sensor, so that it checks
//! the readings as the sensor gives them), its limits from `[safety]` and, where the table
//! leaves them, from the scenario; and the sensor faults in front of it.

use super::super::error::ScenarioError;
use super::super::fault_spec::FaultSpec;
use super::super::planned::PlannedReference;
use super::super::spec::Scenario;
use crate::control::safety::{SafetyLimits, SensorLimits, Supervised};
use crate::control::task_frame::TaskFrame;
use crate::control::Controller;
use crate::model::{JointVector, RobotModel};
use crate::sim::faults::{FaultySensor, SensorFault};
use nalgebra::{SVector, Vector3};

/// Step at which the reference is sampled for the default workspace box, s.
const BOX_STEP_S: f64 = 0.01;

/// The supervisor's limits for `scenario` on `robot` along `reference` (`duration` s long),
/// starting at joints `q0`, with actuator limits `effort`.
#[must_use]
pub fn limits<const N: usize, R: RobotModel<N>>(
    scenario: &Scenario,
    robot: &R,
    reference: &dyn PlannedReference<N>,
    duration: f64,
    q0: &JointVector<N>,
    effort: &JointVector<N>,
) -> SafetyLimits<f64, N> {
    let s = &scenario.safety;
    let force_n = scenario.force.as_ref().map(|f| f.value_n.abs());
    let noise = scenario.sensor.noise_n;
    let workspace = s.workspace.unwrap_or_else(|| {
        let trajectory = reference.trajectory();
        let start = robot.end_effector_pose(q0);
        let start = Vector3::new(start[(0, 3)], start[(1, 3)], start[(2, 3)]);
        let (mut lo, mut hi) = (start, start);
        let steps = (duration / BOX_STEP_S).ceil() as usize;
        for k in 0..=steps {
            let p = trajectory
                .at((k as f64 * BOX_STEP_S).min(duration))
                .position;
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        }
        let m = Vector3::repeat(s.workspace_margin_m);
        (lo - m, hi + m)
    });
    let per_joint =
        |v: &Option<Vec<f64>>| v.as_ref().map(|v| SVector::<f64, N>::from_fn(|i, _| v[i]));
    let inside = robot.within_joint_limits(q0);
    let mut l = SafetyLimits::defaults(
        robot.lower_limits(),
        robot.upper_limits(),
        *effort,
        force_n,
        noise,
    );
    if let Some(max) = s.max_force_n {
        l.force.max_n = max;
    }
    l.force.max_rate_n_s = s.max_force_rate_n_s;
    if let Some(rms) = s.oscillation_rms_n {
        l.force.oscillation_rms_n = rms;
    }
    l.force.oscillation_hz = s.oscillation_hz;
    (l.force.loss_fraction, l.force.loss_s) = s.contact_loss;
    l.sensor = SensorLimits {
        range_n: s.sensor_range.0,
        range_nm: s.sensor_range.1,
        frozen_s: s.frozen_s.unwrap_or(l.sensor.frozen_s),
        stale_s: s.stale_s,
        spike_n: s.spike_filter_n,
    };
    l.max_tool_speed_m_s = s.max_tool_speed_m_s;
    l.workspace = Some(workspace);
    // Just past the limits, into the end stops, only where the run starts within the limits
    // (else from the table).
    l.joint_margin = per_joint(&s.joint_margin).or_else(|| {
        (scenario.end_stops && inside)
            .then(|| SVector::repeat(-crate::control::safety::limits::defaults::JOINT_LIMIT_GIVE))
    });
    l.max_joint_speed = per_joint(&s.max_joint_speed);
    l.max_torque_rate = per_joint(&s.max_torque_rate);
    l.reaction = s.reaction;
    l
}

/// The frame a retraction leaves along: the controller's belief of the force surface, or
/// base `z` without force control.
#[must_use]
pub fn retract_frame(scenario: &Scenario) -> TaskFrame {
    scenario
        .force
        .as_ref()
        .map_or(TaskFrame::Fixed(Vector3::z()), |f| {
            TaskFrame::Surface(
                scenario.surfaces[f.surface]
                    .geometry
                    .shifted(f.expected_shift_m),
            )
        })
}

/// `controller` inside the supervisor (unless `[safety] enabled = false`), behind the
/// scenario's sensor faults (if any).
///
/// # Errors
///
/// [`ScenarioError`] on `faults` if there are more sensor faults than a run holds.
pub fn supervise<const N: usize, M: RobotModel<N> + Copy + 'static>(
    scenario: &Scenario,
    model: M,
    limits: SafetyLimits<f64, N>,
    controller: Box<dyn Controller<N>>,
) -> Result<Box<dyn Controller<N>>, ScenarioError> {
    let controller: Box<dyn Controller<N>> = if scenario.safety.enabled {
        Box::new(Supervised::new(
            controller,
            model,
            limits,
            retract_frame(scenario),
        ))
    } else {
        controller
    };
    with_sensor_faults(scenario, controller)
}

/// `controller` behind the scenario's sensor faults (if any).
///
/// # Errors
///
/// [`ScenarioError`] on `faults` if there are more sensor faults than a run holds.
pub fn with_sensor_faults<const N: usize>(
    scenario: &Scenario,
    controller: Box<dyn Controller<N>>,
) -> Result<Box<dyn Controller<N>>, ScenarioError> {
    let faults: Vec<SensorFault> = scenario
        .faults
        .iter()
        .filter_map(|f| match f {
            FaultSpec::Sensor(s) => Some(*s),
            _ => None,
        })
        .collect();
    if faults.is_empty() {
        return Ok(controller);
    }
    FaultySensor::new(controller, &faults)
        .map(|f| Box::new(f) as Box<dyn Controller<N>>)
        .map_err(|n| {
            scenario.error(
                "faults",
                format!(
                    "{n} sensor faults; a run holds at most {}",
                    crate::sim::faults::MAX_SENSOR_FAULTS
                ),
            )
        })
}
