//! `armdyn.identify`: the command line's `armdyn identify` (design an excitation, measure it on
//! the simulated plant, fit the base parameters, validate on another trajectory), returning
//! `identification.json`'s content and the validation as arrays.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use armdyn::identification::file::to_json;
use armdyn::identification::{identify as run, Identifiable, Identification, IdentifySettings};

use crate::inputs::output;

fn arrays<'py, const N: usize>(
    py: Python<'py>,
    id: &Identification<N>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let joints = |v: &[nalgebra::SVector<f64, N>]| -> Vec<f64> {
        v.iter().flat_map(|x| x.iter().copied()).collect()
    };
    let vector = |v: &[f64]| output(py, v.to_vec(), 1, false, &[v.len()]);
    d.set_item(
        "base_parameters_estimated",
        vector(id.estimate.weighted.as_slice())?,
    )?;
    d.set_item(
        "base_parameters_ordinary_ls",
        vector(id.estimate.ordinary.as_slice())?,
    )?;
    d.set_item("base_parameters_true", vector(id.truth.as_slice())?)?;
    d.set_item("base_parameter_names", id.base.names())?;
    let v = &id.validation;
    let k = v.t.len();
    let validation = PyDict::new(py);
    validation.set_item("t", output(py, v.t.clone(), k, true, &[])?)?;
    validation.set_item("q", output(py, joints(&v.q), k, true, &[N])?)?;
    validation.set_item("qd", output(py, joints(&v.qd), k, true, &[N])?)?;
    validation.set_item("qdd", output(py, joints(&v.qdd), k, true, &[N])?)?;
    validation.set_item("tau", output(py, joints(&v.tau), k, true, &[N])?)?;
    validation.set_item("tau_true", output(py, joints(&v.tau_true), k, true, &[N])?)?;
    validation.set_item(
        "tau_predicted",
        output(
            py,
            id.validation_predicted.as_slice().to_vec(),
            k,
            true,
            &[N],
        )?,
    )?;
    validation.set_item("rms_error_pct", vector(&id.validation_error_pct)?)?;
    validation.set_item(
        "rms_error_noise_free_pct",
        vector(&id.validation_error_noise_free_pct)?,
    )?;
    d.set_item("validation", validation)?;
    Ok(d)
}

fn report<'py, const N: usize, R: Identifiable<N>>(
    py: Python<'py>,
    robot: &R,
    settings: IdentifySettings,
) -> PyResult<Bound<'py, PyDict>> {
    let id = py
        .detach(|| run(robot, &settings))
        .map_err(|e| PyRuntimeError::new_err(format!("identifying {}: {e}", R::NAME)))?;
    let json =
        serde_json::to_string(&to_json(&id)).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    let d: Bound<'py, PyDict> = py
        .import("json")?
        .call_method1("loads", (json,))?
        .cast_into()?;
    d.set_item("arrays", arrays(py, &id)?)?;
    Ok(d)
}

/// Identifies `robot` on its simulated plant with the command line's options; the content of
/// `identification.json`, plus `arrays` (the estimate and the validation as numpy arrays).
#[pyfunction]
#[pyo3(signature = (robot, *, noise_pct = 1.0, friction = false, seed = 1, evaluations = 1500))]
pub fn identify<'py>(
    py: Python<'py>,
    robot: &str,
    noise_pct: f64,
    friction: bool,
    seed: u64,
    evaluations: usize,
) -> PyResult<Bound<'py, PyDict>> {
    if !(noise_pct.is_finite() && (0.0..=100.0).contains(&noise_pct)) {
        return Err(PyValueError::new_err(format!(
            "noise_pct: {noise_pct} is not a percentage in [0, 100]"
        )));
    }
    if evaluations == 0 {
        return Err(PyValueError::new_err("evaluations: must be at least 1"));
    }
    let mut settings = IdentifySettings::new(noise_pct, friction, seed);
    settings.excitation.evaluations = evaluations;
    let name = robot.replace('-', "_");
    let name = name.as_str();
    armdyn_generated::for_each_robot!(return_for_robot, name, |r| report(py, r, settings); armdyn::model);
    for_each_own_robot!(return_for_robot, name, |r| report(py, r, settings); crate::own);
    Err(PyValueError::new_err(format!(
        "robot: no robot called {robot:?} (one of {})",
        crate::model::names().join(", ")
    )))
}
