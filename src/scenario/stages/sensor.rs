//! Stage 5 ([`tool_compensation`] first, [`sensor`] last, the safety stage between them): the
//! force sensor the controller reads (none for an ideal one): at the tool point
//! in base axes (the thesis's), or mounted before a tool, with the tool's weight compensated
//! and the bias tared by the controller ([`ToolCompensation`]); the tare window checked
//! against the reference (at rest, clear of every surface from the start to its end).

use super::super::controllers::GainReport;
use super::super::error::ScenarioError;
use super::super::planned::PlannedReference;
use super::super::spec::Scenario;
use crate::contact::ForceSensor;
use crate::control::selection::SelectionPolicy;
use crate::control::sensed::Sensed;
use crate::control::sensed_behind_tool::SensedBehindTool;
use crate::control::task_frame::TaskFrame;
use crate::control::tool_compensation::{
    TareWindow, ToolCompensation, TARE_MAX_RATE_RAD_S, TARE_MAX_SPEED_M_S,
};
use crate::control::Controller;
use crate::model::{RobotModel, SensorMount, Wrench};

/// The scenario's force sensor (`None` for an ideal one, at the tool point).
///
/// # Errors
///
/// [`ScenarioError`] on `sensor` if its settings are unusable.
pub fn force_sensor(scenario: &Scenario) -> Result<Option<ForceSensor>, ScenarioError> {
    let s = scenario.sensor;
    if s.is_ideal() {
        return Ok(None);
    }
    // The bias and noise act in the sensor frame.
    let noise = Wrench::new(s.noise_n, s.noise_n, s.noise_n, 0.0, 0.0, 0.0);
    let bias = Wrench::new(0.0, 0.0, s.bias_n, 0.0, 0.0, 0.0);
    ForceSensor::new(bias, noise, s.cutoff_hz, s.seed)
        .map(Some)
        .map_err(|e| scenario.error("sensor", e.to_string()))
}

/// Whether the sensor sits before a tool (`[sensor] frame`) or is tared (`tare_s`): the
/// controller then compensates the tool and the bias ([`tool_compensation`]).
fn behind_tool(scenario: &Scenario) -> bool {
    scenario.sensor.mount.is_some() || scenario.sensor.tare.is_some()
}

/// Stage 5, first: `controller` with the tool's weight compensated and the bias tared
/// ([`ToolCompensation`], on the robot `model` for the tool's pose) where the sensor sits
/// before a tool or is tared; the tare window checked against `reference` (a run `duration` s
/// long). Unchanged otherwise.
///
/// # Errors
///
/// [`ScenarioError`] on `sensor.tare_s` for a window the tool is not at rest in, or touches a
/// surface before the window ends, or that ends after the run or after a timed switch.
pub fn tool_compensation<const N: usize, M: RobotModel<N> + Copy + 'static>(
    scenario: &Scenario,
    model: M,
    reference: &dyn PlannedReference<N>,
    duration: f64,
    controller: Box<dyn Controller<N>>,
) -> Result<Box<dyn Controller<N>>, ScenarioError> {
    let s = scenario.sensor;
    if !behind_tool(scenario) {
        return Ok(controller);
    }
    if let Some(w) = s.tare {
        check_tare(scenario, reference, duration, w)?;
    }
    let mount = s.mount.unwrap_or_else(SensorMount::at_tool_point);
    Ok(Box::new(ToolCompensation::new(
        controller,
        model,
        mount,
        s.compensate_tool,
        s.tare,
    )))
}

/// Stage 5, last: `controller` (its safety stage included) reading the contact through the
/// scenario's sensor (unchanged for an ideal one at the tool point), on the robot `model`
/// (for the tool's pose); the sensor is added to `gains`' note.
///
/// # Errors
///
/// As [`force_sensor`].
pub fn sensor<const N: usize, M: RobotModel<N> + Copy + 'static>(
    scenario: &Scenario,
    model: M,
    controller: Box<dyn Controller<N>>,
    gains: &mut GainReport,
) -> Result<Box<dyn Controller<N>>, ScenarioError> {
    let s = scenario.sensor;
    let Some(sensor) = force_sensor(scenario)? else {
        return Ok(controller);
    };
    let low_pass = s
        .cutoff_hz
        .map_or("none".to_string(), |c| format!("{c} Hz"));
    if !behind_tool(scenario) {
        gains.note = format!(
            "{}; force sensor: noise {} N (1 sigma per axis), bias {} N on fz, low-pass {low_pass}, seed {}",
            gains.note, s.noise_n, s.bias_n, s.seed
        );
        return Ok(Box::new(Sensed::new(controller, sensor)));
    }
    let mount = s.mount.unwrap_or_else(SensorMount::at_tool_point);
    gains.note = format!(
        "{}; force sensor before the tool: origin [{}, {}, {}] m (tool frame), tool {} kg at [{}, {}, {}] m (sensor frame), weight {}, bias {} N on the sensor's z, {}, noise {} N (1 sigma per axis), low-pass {low_pass}, seed {}",
        gains.note,
        mount.origin_m.x,
        mount.origin_m.y,
        mount.origin_m.z,
        mount.tool_mass_kg,
        mount.tool_com_m.x,
        mount.tool_com_m.y,
        mount.tool_com_m.z,
        if s.compensate_tool { "compensated" } else { "not compensated" },
        s.bias_n,
        s.tare.map_or("not tared".to_string(), |w| format!(
            "tared over [{}, {}] s",
            w.start_s, w.end_s
        )),
        s.noise_n,
        s.seed
    );
    Ok(Box::new(SensedBehindTool::behind_tool(
        controller, model, mount, sensor,
    )))
}

/// The step at which the tare window is checked against the reference, s.
const TARE_CHECK_STEP_S: f64 = 1e-3;

/// Refuses a tare window in which the reference moves, or before whose end it touches a
/// surface (as it really is), or that ends after the run or a timed switch.
fn check_tare<const N: usize>(
    scenario: &Scenario,
    reference: &dyn PlannedReference<N>,
    duration: f64,
    w: TareWindow,
) -> Result<(), ScenarioError> {
    const KEY: &str = "sensor.tare_s";
    if w.end_s >= duration {
        return Err(scenario.error(
            KEY,
            format!(
                "ends at {} s, not before the end of the run ({} s)",
                w.end_s, duration
            ),
        ));
    }
    if let Some(SelectionPolicy::Time { switch_s }) = scenario.selection {
        if switch_s < w.end_s {
            return Err(scenario.error(
                KEY,
                format!(
                    "ends at {} s, after the switch to force control (selection.switch_s = {switch_s} s): force control needs the tare",
                    w.end_s
                ),
            ));
        }
    }
    let trajectory = reference.trajectory();
    let steps = (w.end_s / TARE_CHECK_STEP_S).ceil() as usize;
    for k in 0..=steps {
        let t = (k as f64 * TARE_CHECK_STEP_S).min(w.end_s);
        let c = trajectory.at(t);
        if t >= w.start_s
            && (c.velocity.norm() > TARE_MAX_SPEED_M_S
                || c.angular_velocity.norm() > TARE_MAX_RATE_RAD_S)
        {
            return Err(scenario.error(
                KEY,
                format!(
                    "the tool moves during the tare: at t = {t:.3} s the reference moves at {:.1} mm/s and {:.3} rad/s (at most {} mm/s and {} rad/s)",
                    c.velocity.norm() * 1e3,
                    c.angular_velocity.norm(),
                    TARE_MAX_SPEED_M_S * 1e3,
                    TARE_MAX_RATE_RAD_S
                ),
            ));
        }
        for (i, surface) in scenario.surfaces.iter().enumerate() {
            let gap = TaskFrame::Surface(surface.geometry).signed_distance(&c.position);
            if gap.is_some_and(|g| g <= TARE_CLEARANCE_M) {
                return Err(scenario.error(
                    KEY,
                    format!(
                        "the tool touches surfaces[{i}] before the tare ends: at t = {t:.3} s the reference is {:.1} mm from it (at least {} mm until {} s)",
                        gap.unwrap_or(0.0) * 1e3,
                        TARE_CLEARANCE_M * 1e3,
                        w.end_s
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// How far from every surface the reference must stay until the tare ends, m.
pub const TARE_CLEARANCE_M: f64 = 0.002;
