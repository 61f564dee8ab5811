//! Scenarios from Python: a file or a dict read and checked as `armdyn run scenario` reads it,
//! run with the GIL released, its samples returned as numpy arrays and its metrics as the
//! command line's `metrics.json`.

use std::path::{Path, PathBuf};

use numpy::PyArrayDyn;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use armdyn::scenario::{controller_model_for, metrics_json, prepare_for, Scenario, ScenarioRobot};
use armdyn::sim::Sample;

use crate::inputs::output;

pyo3::create_exception!(
    _native,
    ScenarioError,
    PyValueError,
    "A scenario that cannot run: its `file`, `key` (a dotted path), `line` (from 1, or None) and `rule`."
);

pyo3::create_exception!(
    _native,
    SimulationError,
    PyRuntimeError,
    "A simulation that broke down (a non-finite state, a model that cannot be evaluated)."
);

/// The library's scenario error as a Python `ScenarioError` carrying its parts.
pub fn scenario_error(py: Python<'_>, e: &armdyn::scenario::ScenarioError) -> PyErr {
    let err = ScenarioError::new_err(e.to_string());
    let value = err.value(py);
    let _ = value.setattr("file", e.file.as_str());
    let _ = value.setattr("key", e.key.as_str());
    let _ = value.setattr("rule", e.rule.as_str());
    let _ = value.setattr("line", e.line);
    err
}

/// The scenario a Python argument names: a path (str or `os.PathLike`), or a dict of the
/// file's tables (written as TOML; relative file names resolve in `base_dir`, default the
/// working folder). The sweep table is kept. Returns the scenario and the folder its relative
/// names resolve in.
pub fn load(
    py: Python<'_>,
    source: &Bound<'_, PyAny>,
    base_dir: Option<PathBuf>,
) -> PyResult<(Scenario, PathBuf)> {
    let tables = [armdyn::sweep::TABLE];
    if let Ok(dict) = source.cast::<PyDict>() {
        let json: String = py
            .import("json")?
            .call_method1("dumps", (dict,))
            .map_err(|e| {
                PyValueError::new_err(format!("scenario: the dict is not plain data ({e})"))
            })?
            .extract()?;
        let text =
            dict_to_toml(&json).map_err(|e| PyValueError::new_err(format!("scenario: {e}")))?;
        let dir = base_dir.unwrap_or_else(|| PathBuf::from("."));
        let s = Scenario::parse_with("<dict>", &text, &dir, &tables)
            .map_err(|e| scenario_error(py, &e))?;
        return Ok((s, dir));
    }
    let path: PathBuf = source.extract().map_err(|_| {
        PyValueError::new_err("scenario: expected a file path (str or os.PathLike) or a dict of the scenario's tables")
    })?;
    let s = Scenario::load_with(&path, &tables).map_err(|e| scenario_error(py, &e))?;
    let dir = path
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    Ok((s, dir))
}

/// JSON text of a dict as TOML text.
fn dict_to_toml(json: &str) -> Result<String, String> {
    let value: serde_json::Value = serde_json::from_str(json).map_err(|e| e.to_string())?;
    let table = toml::Value::try_from(value)
        .map_err(|e| format!("cannot be written as TOML ({e}); TOML has no null"))?;
    toml::to_string(&table).map_err(|e| format!("cannot be written as TOML ({e})"))
}

/// Reads scenario text `source` named `file` whose relative names resolve in `dir`.
pub fn parse(py: Python<'_>, source: &str, file: &str, dir: &str) -> PyResult<Scenario> {
    Scenario::parse_with(file, source, Path::new(dir), &[armdyn::sweep::TABLE])
        .map_err(|e| scenario_error(py, &e))
}

/// Applies `armdyn run`'s options to `s`.
pub fn apply_options(
    py: Python<'_>,
    s: &mut Scenario,
    safety: Option<bool>,
    controller_model: Option<&str>,
) -> PyResult<()> {
    if let Some(on) = safety {
        s.safety.enabled = on;
    }
    if let Some(m) = controller_model {
        s.controller_model = controller_model_for(s, m).map_err(|e| {
            scenario_error(
                py,
                &s.error("controller_model", format!("controller_model={m:?}: {e}")),
            )
        })?;
    }
    Ok(())
}

/// Runs scenario `source` (see [`load`]) and returns its samples as arrays and its metrics.
#[pyfunction]
#[pyo3(signature = (scenario, *, base_dir = None, precision = "reference", safety = None, controller_model = None))]
pub fn run_scenario<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, PyAny>,
    base_dir: Option<PathBuf>,
    precision: &str,
    safety: Option<bool>,
    controller_model: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let (mut s, _) = load(py, scenario, base_dir)?;
    apply_options(py, &mut s, safety, controller_model)?;
    let precision = match precision {
        "reference" => None,
        "f64" => Some(armdyn::scenario::Precision::F64),
        "f32" => Some(armdyn::scenario::Precision::F32),
        other => {
            return Err(PyValueError::new_err(format!(
                "precision: {other:?} is not one of \"reference\", \"f64\", \"f32\""
            )))
        }
    };
    armdyn::with_robot_named!(s.robot.as_str(), |robot: R, N, _module| {
        run_on(py, &s, precision, robot)
    })
    .unwrap_or_else(|| Err(scenario_error(py, &s.error("robot", "unknown robot"))))
}

/// [`run_scenario`] on the scenario's robot `robot`.
fn run_on<'py, const N: usize, R: ScenarioRobot<N>>(
    py: Python<'py>,
    s: &Scenario,
    precision: Option<armdyn::scenario::Precision>,
    robot: R,
) -> PyResult<Bound<'py, PyDict>> {
    // The error of a failed run: the scenario's (before anything ran) or the simulation's.
    #[allow(clippy::result_large_err)]
    let recorded = py.detach(|| {
        let prepared = match precision {
            None => prepare_for(s, robot),
            Some(p) => armdyn::scenario::prepare_deployed_for(s, robot, p),
        }
        .map_err(Err)?;
        prepared.execute(s, |_| {}).map_err(Ok)
    });
    let recorded = match recorded {
        Ok(o) => o,
        Err(Err(e)) => return Err(scenario_error(py, &e)),
        Err(Ok(e)) => {
            return Err(SimulationError::new_err(format!(
                "{}: simulation stopped: {e}",
                s.file
            )))
        }
    };
    let outcome = &recorded.outcome;
    let d = PyDict::new(py);
    columns::<N>(py, &recorded.samples, &d)?;
    let metrics = serde_json::to_string(&metrics_json(s, outcome))
        .map_err(|e| PyRuntimeError::new_err(format!("metrics: {e}")))?;
    d.set_item(
        "metrics",
        py.import("json")?.call_method1("loads", (metrics,))?,
    )?;
    d.set_item("robot", outcome.robot)?;
    d.set_item("joint_names", outcome.joint_names.clone())?;
    d.set_item("name", s.name.clone())?;
    Ok(d)
}

/// Puts every sample's columns into `d`.
fn columns<const N: usize>(py: Python<'_>, s: &[Sample<N>], d: &Bound<'_, PyDict>) -> PyResult<()> {
    let k = s.len();
    let put = |name: &str, width: usize, f: &dyn Fn(&Sample<N>, &mut Vec<f64>)| -> PyResult<()> {
        let mut v = Vec::with_capacity(k * width);
        for x in s {
            f(x, &mut v);
        }
        let shape: Vec<usize> = if width == 0 { vec![] } else { vec![width] };
        let a: Bound<'_, PyArrayDyn<f64>> = output(py, v, k, true, &shape)?;
        d.set_item(name, a)
    };
    let joints =
        |v: &mut Vec<f64>, x: &nalgebra::SVector<f64, N>| v.extend_from_slice(x.as_slice());
    let quat = |v: &mut Vec<f64>, q: &nalgebra::UnitQuaternion<f64>| {
        // Scalar last, as Pinocchio's and SciPy's: (x, y, z, w).
        v.extend_from_slice(q.coords.as_slice());
    };
    put("t", 0, &|x, v| v.push(x.t))?;
    put("q", N, &|x, v| joints(v, &x.q))?;
    put("qd", N, &|x, v| joints(v, &x.qd))?;
    put("tau", N, &|x, v| joints(v, &x.tau))?;
    put("tau_command", N, &|x, v| joints(v, &x.tau_command))?;
    put("position", 3, &|x, v| {
        v.extend_from_slice(x.position.as_slice())
    })?;
    put("orientation", 4, &|x, v| quat(v, &x.orientation))?;
    put("wrench", 6, &|x, v| {
        v.extend_from_slice(x.wrench.as_slice())
    })?;
    put("measured_wrench", 6, &|x, v| {
        v.extend_from_slice(x.measured_wrench.as_slice())
    })?;
    put("q_ref", N, &|x, v| joints(v, &x.setpoint.joint.q))?;
    put("qd_ref", N, &|x, v| joints(v, &x.setpoint.joint.qd))?;
    put("qdd_ref", N, &|x, v| joints(v, &x.setpoint.joint.qdd))?;
    put("position_ref", 3, &|x, v| {
        v.extend_from_slice(x.setpoint.cartesian.position.as_slice())
    })?;
    put("orientation_ref", 4, &|x, v| {
        quat(v, &x.setpoint.cartesian.orientation)
    })?;
    put("wrench_ref", 6, &|x, v| {
        v.extend_from_slice(x.setpoint.wrench.as_slice())
    })?;
    let fc: Vec<bool> = s.iter().map(|x| x.force_controlled).collect();
    d.set_item("force_controlled", numpy::PyArray1::from_vec(py, fc))?;
    Ok(())
}
