//! A scenario's controller alone, stepped from Python (`armdyn.Controller`): the library's
//! `SteppedController` behind an object-safe interface on slices, for any robot.

use std::path::{Path, PathBuf};

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1, PyUntypedArrayMethods, ToPyArray};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use armdyn::model::{JointVector, Wrench};
use armdyn::scenario::{
    metrics_json, write_outputs_for, PreparedRun, Scenario, ScenarioRobot, StepOutcome,
    SteppedController,
};

use crate::scenario::{apply_options, load, scenario_error};

/// A stepped controller of any joint count, on slices.
trait Stepper {
    fn dof(&self) -> usize;
    fn name(&self) -> &'static str;
    fn period_s(&self) -> f64;
    fn start(&self) -> Vec<f64>;
    fn effort_limits(&self) -> Vec<f64>;
    fn reset(&mut self, t: f64, q: &[f64], qd: &[f64]);
    fn step(&mut self, t: f64, q: &[f64], qd: &[f64], wrench: &[f64], tau: &mut [f64]);
    fn report<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>>;
    fn record(&mut self);
    fn plant<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>>;
    /// The recorded run's metrics (`metrics.json`'s text), its files written into `out`.
    fn finish(self: Box<Self>, scenario: &Scenario, out: Option<&Path>) -> Result<String, String>;
}

impl<const N: usize, R: ScenarioRobot<N>> Stepper for SteppedController<N, R> {
    fn dof(&self) -> usize {
        N
    }
    fn name(&self) -> &'static str {
        SteppedController::name(self)
    }
    fn period_s(&self) -> f64 {
        SteppedController::period_s(self)
    }
    fn start(&self) -> Vec<f64> {
        SteppedController::start(self).as_slice().to_vec()
    }
    fn effort_limits(&self) -> Vec<f64> {
        SteppedController::effort_limits(self).as_slice().to_vec()
    }
    fn reset(&mut self, t: f64, q: &[f64], qd: &[f64]) {
        SteppedController::reset(
            self,
            t,
            &JointVector::<N>::from_column_slice(q),
            &JointVector::<N>::from_column_slice(qd),
        );
    }
    fn step(&mut self, t: f64, q: &[f64], qd: &[f64], wrench: &[f64], tau: &mut [f64]) {
        let out = SteppedController::step(
            self,
            t,
            &JointVector::<N>::from_column_slice(q),
            &JointVector::<N>::from_column_slice(qd),
            &Wrench::from_column_slice(wrench),
        );
        tau.copy_from_slice(out.as_slice());
    }
    fn report<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        outcome_dict(py, SteppedController::report(self))
    }
    fn record(&mut self) {
        SteppedController::record(self);
    }
    fn plant<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        plant_dict(py, self.prepared())
    }
    fn finish(self: Box<Self>, scenario: &Scenario, out: Option<&Path>) -> Result<String, String> {
        let robot = self.prepared().robot;
        let outcome = SteppedController::outcome(*self, scenario)
            .ok_or_else(|| "no step was recorded: call record() before the run".to_string())?;
        if let Some(dir) = out {
            write_outputs_for(dir, scenario, &outcome, true, &robot)
                .map_err(|e| format!("{e:#}"))?;
        }
        let metrics = metrics_json(scenario, &outcome.outcome);
        serde_json::to_string(&metrics).map_err(|e| e.to_string())
    }
}

/// The report of a step as a dict of plain values and numpy arrays.
fn outcome_dict<'py, const N: usize>(
    py: Python<'py>,
    r: &StepOutcome<N>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("t", r.t)?;
    d.set_item("mode", r.mode.name())?;
    d.set_item("force_ref", r.force_ref.as_slice().to_pyarray(py))?;
    d.set_item("force_measured", r.force_measured.as_slice().to_pyarray(py))?;
    d.set_item("force_error_n", r.force_error_n)?;
    d.set_item("trips", r.trips)?;
    d.set_item("first_trip", r.first_trip.map(|c| c.name()))?;
    d.set_item("command", r.command.as_slice().to_pyarray(py))?;
    d.set_item("saturated", r.saturated.to_vec())?;
    Ok(d)
}

/// A vector as a list.
fn list(v: &nalgebra::Vector3<f64>) -> Vec<f64> {
    v.as_slice().to_vec()
}

/// What a plant of one's own needs to simulate the scenario's run: the robot (its URDF for
/// the registry's robots), timing, initial state, limits, gravity, the real surfaces and the
/// environment's faults.
fn plant_dict<'py, const N: usize, R: ScenarioRobot<N>>(
    py: Python<'py>,
    run: &PreparedRun<N, R>,
) -> PyResult<Bound<'py, PyDict>> {
    use armdyn::report::view::surface_json;
    let d = PyDict::new(py);
    let c = &run.config;
    d.set_item("robot", R::NAME)?;
    d.set_item("urdf", crate::model::urdf(R::NAME))?;
    d.set_item("tool_link", format!("{}_tool", R::NAME))?;
    d.set_item("joint_names", R::JOINT_NAMES.to_vec())?;
    d.set_item("gravity", R::GRAVITY.to_vec())?;
    d.set_item("duration_s", c.duration)?;
    d.set_item("plant_dt_s", c.plant_dt)?;
    d.set_item("control_dt_s", c.control_dt)?;
    d.set_item("q0", c.q0.as_slice().to_vec())?;
    d.set_item("qd0", c.qd0.as_slice().to_vec())?;
    d.set_item("effort_limits", c.effort_limits.as_slice().to_vec())?;
    d.set_item("joint_limits", R::JOINT_LIMITS.to_vec())?;
    d.set_item("end_stops", c.end_stops.is_some())?;
    let surfaces = pyo3::types::PyList::empty(py);
    let json = py.import("json")?;
    for s in run.environment.scene.surfaces() {
        // The shape's settings as `scene.json` writes them (`kind` first).
        let x: Bound<'_, PyDict> = json
            .call_method1("loads", (surface_json(&s.geometry).to_string(),))?
            .cast_into()?;
        x.set_item("stiffness", s.stiffness)?;
        x.set_item("damping", s.damping)?;
        x.set_item("friction", s.friction)?;
        surfaces.append(x)?;
    }
    d.set_item("surfaces", surfaces)?;
    let env = &run.environment;
    match env.edge {
        Some(e) => {
            let x = PyDict::new(py);
            x.set_item("surface", e.surface)?;
            x.set_item("point", list(&e.point))?;
            x.set_item("beyond", list(&e.beyond))?;
            d.set_item("edge", x)?;
        }
        None => d.set_item("edge", py.None())?,
    }
    d.set_item("stiffness_step", env.stiffness_step)?;
    d.set_item("payload", env.payload.map(|(m, t, g)| (m, t, list(&g))))?;
    Ok(d)
}

/// Reads `obj` as exactly `len` numbers: a contiguous `float64` array as it is (no copy
/// through numpy's conversion), else anything numpy reads as a vector. Non-finite numbers
/// are refused unless `finite_only` is false.
fn numbers(
    obj: &Bound<'_, PyAny>,
    name: &str,
    len: usize,
    finite_only: bool,
) -> PyResult<Vec<f64>> {
    let values: Vec<f64> = match obj.extract::<PyReadonlyArray1<'_, f64>>() {
        Ok(a) if a.is_contiguous() => a.as_slice()?.to_vec(),
        _ => {
            let np = obj.py().import("numpy")?;
            let array = np.call_method1("asarray", (obj, "float64")).map_err(|e| {
                PyValueError::new_err(format!("{name}: cannot be read as numbers ({e})"))
            })?;
            let array = array
                .cast_into::<numpy::PyArrayDyn<f64>>()
                .map_err(|_| PyValueError::new_err(format!("{name}: cannot be read as numbers")))?;
            if array.ndim() != 1 {
                return Err(PyValueError::new_err(format!(
                    "{name}: expected shape ({len},), got {:?}",
                    array.shape()
                )));
            }
            array.to_vec()?
        }
    };
    if values.len() != len {
        return Err(PyValueError::new_err(format!(
            "{name}: expected {len} numbers, got {}",
            values.len()
        )));
    }
    if finite_only {
        if let Some(i) = values.iter().position(|x| !x.is_finite()) {
            return Err(PyValueError::new_err(format!(
                "{name}[{i}] = {} is not a finite number",
                values[i]
            )));
        }
    }
    Ok(values)
}

/// A scenario's controller alone, for a loop of your own (a simulator, a robot's driver):
/// `reset(t, q, qd)`, then `step(t, q, qd, wrench)` every `period_s` seconds, and `report()`
/// after a step. The position and force laws, selection, the sensor model, tool compensation
/// and the supervisor are the scenario's, exactly as `run_scenario` simulates them.
#[pyclass(module = "armdyn._native", name = "Controller", unsendable)]
pub struct Controller {
    inner: Option<Box<dyn Stepper>>,
    scenario: Scenario,
    tau: Vec<f64>,
}

/// The error of a call after `finish`.
fn finished() -> PyErr {
    PyValueError::new_err("this controller's run is finished (finish() was called)")
}

impl Controller {
    fn inner(&self) -> PyResult<&dyn Stepper> {
        self.inner.as_deref().ok_or_else(finished)
    }

    /// `t` finite and `q`, `qd` as `dof` finite numbers each, or the error naming them.
    fn state(
        &self,
        t: f64,
        q: &Bound<'_, PyAny>,
        qd: &Bound<'_, PyAny>,
    ) -> PyResult<(Vec<f64>, Vec<f64>)> {
        let n = self.inner()?.dof();
        if !t.is_finite() {
            return Err(PyValueError::new_err(format!(
                "t = {t} is not a finite time"
            )));
        }
        Ok((numbers(q, "q", n, true)?, numbers(qd, "qd", n, true)?))
    }

    fn inner_mut(&mut self) -> PyResult<&mut Box<dyn Stepper>> {
        self.inner.as_mut().ok_or_else(finished)
    }
}

#[pymethods]
impl Controller {
    /// The controller of `scenario` (a file path or a dict of its tables, as for
    /// `run_scenario`), with `armdyn run`'s options.
    #[new]
    #[pyo3(signature = (scenario, *, base_dir = None, safety = None, controller_model = None))]
    fn new(
        py: Python<'_>,
        scenario: &Bound<'_, PyAny>,
        base_dir: Option<PathBuf>,
        safety: Option<bool>,
        controller_model: Option<&str>,
    ) -> PyResult<Self> {
        let (mut s, _) = load(py, scenario, base_dir)?;
        apply_options(py, &mut s, safety, controller_model)?;
        let inner = armdyn::with_robot_named!(s.robot.as_str(), |robot: R, N, _module| {
            SteppedController::new(&s, robot).map(|c| Box::new(c) as Box<dyn Stepper>)
        })
        .ok_or_else(|| PyValueError::new_err(format!("unknown robot `{}`", s.robot)))?
        .map_err(|e| scenario_error(py, &e))?;
        let tau = vec![0.0; inner.dof()];
        Ok(Self {
            inner: Some(inner),
            scenario: s,
            tau,
        })
    }

    /// Degrees of freedom.
    #[getter]
    fn dof(&self) -> PyResult<usize> {
        Ok(self.inner()?.dof())
    }

    /// The controller's name.
    #[getter]
    fn name(&self) -> PyResult<&'static str> {
        Ok(self.inner()?.name())
    }

    /// The control period the controller expects, s.
    #[getter]
    fn period_s(&self) -> PyResult<f64> {
        Ok(self.inner()?.period_s())
    }

    /// The joints the scenario's run starts from, rad or m.
    #[getter]
    fn start<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(self.inner()?.start().to_pyarray(py))
    }

    /// The effort limits the torques are clipped to, N m or N.
    #[getter]
    fn effort_limits<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(self.inner()?.effort_limits().to_pyarray(py))
    }

    /// Starts a run with the arm at `q`, `qd` (finite, `(dof,)`) at the loop's time `t`, s:
    /// the scenario's time is `t_step - t` from now on.
    fn reset(&mut self, t: f64, q: &Bound<'_, PyAny>, qd: &Bound<'_, PyAny>) -> PyResult<()> {
        let (q, qd) = self.state(t, q, qd)?;
        self.inner_mut()?.reset(t, &q, &qd);
        Ok(())
    }

    /// One control period at time `t` (s) with the arm at `q`, `qd` and the tool exerting
    /// `wrench` (`(6,)`, `[fx fy fz tx ty tz]`, base frame, N and N m) on the environment:
    /// the joint torques `(dof,)` to hold until the next step, within the effort limits. A
    /// non-finite wrench is passed on (the supervisor judges the sensor); `q`, `qd` and `t`
    /// must be finite.
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        t: f64,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        wrench: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let (q, qd) = self.state(t, q, qd)?;
        let wrench = numbers(wrench, "wrench", 6, false)?;
        let tau = &mut self.tau;
        match self.inner.as_mut() {
            Some(inner) => inner.step(t, &q, &qd, &wrench, tau),
            None => return Err(finished()),
        }
        Ok(self.tau.to_pyarray(py))
    }

    /// What the last step did: `t`, `mode` (`"position"`, `"force"` or `"tripped"`),
    /// `force_ref` and `force_measured` (N, base frame), `force_error_n` (the force missing
    /// along the desired one), `trips` and `first_trip` (the supervisor's), `command` (the
    /// torques before clipping) and `saturated` (per joint).
    fn report<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.inner()?.report(py)
    }

    /// What a plant of one's own needs to simulate the scenario's run (a dict): `robot`,
    /// `urdf` (the registry's robots' URDF, else None), `tool_link`, `joint_names`, `gravity`,
    /// `duration_s`, `plant_dt_s`, `control_dt_s`, `q0`, `qd0`, `effort_limits`,
    /// `joint_limits`, `end_stops`, `surfaces` (each with its `kind` and geometry, m, and its
    /// `stiffness` N/m, `damping` N s/m and Coulomb `friction`), and the environment's faults:
    /// `edge` (a surface that ends: `surface`, `point`, `beyond`), `stiffness_step`
    /// (`(surface, from_s, factor)`) and `payload` (`(mass_kg, drop_s, gravity)`).
    fn plant<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.inner()?.plant(py)
    }

    /// Keeps every step from now on (until `reset`) as a sample of the run, for `finish`.
    fn record(&mut self) -> PyResult<()> {
        self.inner_mut()?.record();
        Ok(())
    }

    /// Ends the run: the metrics of the recorded steps as `armdyn run scenario` writes them
    /// (`metrics.json` as a dict), and with `out` its files written there (`trajectory.csv`,
    /// `metrics.json`, the figures and `view.html`). The controller cannot step after it.
    #[pyo3(signature = (out = None))]
    fn finish<'py>(
        &mut self,
        py: Python<'py>,
        out: Option<PathBuf>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let inner = self.inner.take().ok_or_else(finished)?;
        let text = inner
            .finish(&self.scenario, out.as_deref())
            .map_err(PyValueError::new_err)?;
        py.import("json")?.call_method1("loads", (text,))
    }

    fn __repr__(&self) -> String {
        match &self.inner {
            Some(i) => format!("Controller({:?}, dof={})", i.name(), i.dof()),
            None => "Controller(finished)".to_string(),
        }
    }
}
