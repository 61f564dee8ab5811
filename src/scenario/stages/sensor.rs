//! Stage 5: the force sensor the controller reads (none for an ideal one).

use super::super::controllers::GainReport;
use super::super::error::ScenarioError;
use super::super::spec::Scenario;
use crate::contact::{ForceSensor, Sensed};
use crate::control::Controller;
use crate::model::Wrench;

/// The scenario's force sensor (`None` for an ideal one).
///
/// # Errors
///
/// [`ScenarioError`] on `sensor` if its settings are unusable.
pub fn force_sensor(scenario: &Scenario) -> Result<Option<ForceSensor>, ScenarioError> {
    if scenario.sensor.is_ideal() {
        return Ok(None);
    }
    let s = scenario.sensor;
    let noise = Wrench::new(s.noise_n, s.noise_n, s.noise_n, 0.0, 0.0, 0.0);
    let bias = Wrench::new(0.0, 0.0, s.bias_n, 0.0, 0.0, 0.0);
    ForceSensor::new(bias, noise, s.cutoff_hz, s.seed)
        .map(Some)
        .map_err(|e| scenario.error("sensor", e.to_string()))
}

/// Stage 5: `controller` behind the scenario's sensor (unchanged for an ideal one); the
/// sensor is added to `gains`' note.
///
/// # Errors
///
/// As [`force_sensor`].
pub fn sensor<const N: usize>(
    scenario: &Scenario,
    controller: Box<dyn Controller<N>>,
    gains: &mut GainReport,
) -> Result<Box<dyn Controller<N>>, ScenarioError> {
    let Some(sensor) = force_sensor(scenario)? else {
        return Ok(controller);
    };
    let s = scenario.sensor;
    gains.note = format!(
        "{}; force sensor: noise {} N (1 sigma per axis), bias {} N on fz, low-pass {}, seed {}",
        gains.note,
        s.noise_n,
        s.bias_n,
        s.cutoff_hz
            .map_or("none".to_string(), |c| format!("{c} Hz")),
        s.seed
    );
    Ok(Box::new(Sensed::new(controller, sensor)))
}
