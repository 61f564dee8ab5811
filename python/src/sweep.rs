//! Sweeps from Python in chunks: a plan (the scenario as text, for any worker to read again),
//! chunks of trials run anywhere, and the table and summary of all of them. A trial's draws
//! come from the sweep's one generator by its index (`armdyn::sweep::draw_all`), so a trial
//! gives the same result whatever chunk or machine runs it.

use std::path::PathBuf;

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use armdyn::scenario::Scenario;
use armdyn::sweep::{
    draw_all, run_trials, summary_json, Failure, SweepRun, SweepSpec, TrialResult, METRICS,
};

use crate::scenario::{apply_options, load, parse, scenario_error};

/// What a worker needs to run trials: the scenario's text, name and folder, and the options.
#[derive(Clone, Debug, FromPyObject, IntoPyObject)]
#[pyo3(from_item_all)]
pub struct Job {
    source: String,
    file: String,
    dir: String,
    safety: Option<bool>,
    controller_model: Option<String>,
}

fn scenario_and_spec(py: Python<'_>, job: &Job) -> PyResult<(Scenario, SweepSpec)> {
    let mut s = parse(py, &job.source, &job.file, &job.dir)?;
    apply_options(py, &mut s, job.safety, job.controller_model.as_deref())?;
    let spec = SweepSpec::of(&s)
        .map_err(|e| scenario_error(py, &e))?
        .ok_or_else(|| {
            PyValueError::new_err(format!(
                "scenario: {} has no [sweep] table; nothing to vary",
                s.file
            ))
        })?;
    Ok((s, spec))
}

/// Reads and checks a sweep's scenario (its `[sweep]` table, and that the nominal scenario
/// sets up) and returns the job workers run: `(job, columns)`.
#[pyfunction]
#[pyo3(signature = (scenario, *, base_dir = None, safety = None, controller_model = None))]
pub fn sweep_plan(
    py: Python<'_>,
    scenario: &Bound<'_, PyAny>,
    base_dir: Option<PathBuf>,
    safety: Option<bool>,
    controller_model: Option<String>,
) -> PyResult<(Job, Vec<String>)> {
    let (s, dir) = load(py, scenario, base_dir)?;
    let job = Job {
        source: s.source.clone(),
        file: s.file.clone(),
        dir: dir.display().to_string(),
        safety,
        controller_model,
    };
    let (s, spec) = scenario_and_spec(py, &job)?;
    py.detach(|| armdyn::scenario::prepare(&s).map(drop))
        .map_err(|e| scenario_error(py, &e))?;
    Ok((job, spec.columns()))
}

/// One trial's result as it comes back from Python: `(failures, metrics, error)`.
type RowIn = (Vec<String>, Vec<Option<f64>>, Option<String>);

/// One trial's result as plain data: `(failures, metrics, error)`.
type Row = (Vec<&'static str>, Vec<Option<f64>>, Option<String>);

fn row(r: &TrialResult) -> Row {
    (
        r.failures.iter().map(|f| f.name()).collect(),
        r.metrics.clone(),
        r.error.clone(),
    )
}

/// Runs trials `start..stop` of the sweep `job` with `samples` trials seeded `seed`, in
/// parallel on this process's cores, with the GIL released; their results in order.
#[pyfunction]
pub fn sweep_chunk(
    py: Python<'_>,
    job: Job,
    samples: usize,
    seed: u64,
    start: usize,
    stop: usize,
) -> PyResult<Vec<Row>> {
    if !(start <= stop && stop <= samples) {
        return Err(PyValueError::new_err(format!(
            "start, stop: {start}..{stop} is not a range of trials in 0..{samples}"
        )));
    }
    let (s, spec) = scenario_and_spec(py, &job)?;
    let results = py
        .detach(|| {
            let pool = crate::pool::pool()?;
            let draws = draw_all(&spec, samples, seed);
            Ok::<_, String>(pool.install(|| run_trials(&s, &spec, &draws[start..stop], &|| {})))
        })
        .map_err(PyRuntimeError::new_err)?;
    Ok(results.iter().map(row).collect())
}

fn failure(name: &str) -> PyResult<Failure> {
    Failure::ALL
        .into_iter()
        .find(|f| f.name() == name)
        .ok_or_else(|| PyValueError::new_err(format!("rows: no failure reason {name:?}")))
}

/// The per-trial table (columns as lists: `trial`, the drawn columns, `sensor_seed`,
/// `status`, `failures`, every metric, `error`; as `trials.csv`) and the summary (as
/// `summary.json`) of the sweep `job` from the rows of all its trials in order.
#[pyfunction]
pub fn sweep_table<'py>(
    py: Python<'py>,
    job: Job,
    samples: usize,
    seed: u64,
    rows: Vec<RowIn>,
) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyAny>)> {
    if rows.len() != samples {
        return Err(PyValueError::new_err(format!(
            "rows: {} rows for a sweep of {samples} trials",
            rows.len()
        )));
    }
    let (s, spec) = scenario_and_spec(py, &job)?;
    let results = rows
        .into_iter()
        .map(|(failures, metrics, error)| {
            if metrics.len() != METRICS.len() {
                return Err(PyValueError::new_err(format!(
                    "rows: {} metrics in a row, expected {}",
                    metrics.len(),
                    METRICS.len()
                )));
            }
            Ok(TrialResult {
                failures: failures
                    .iter()
                    .map(|f| failure(f))
                    .collect::<PyResult<_>>()?,
                metrics,
                error,
            })
        })
        .collect::<PyResult<Vec<_>>>()?;
    let run = SweepRun {
        draws: draw_all(&spec, samples, seed),
        results,
        elapsed_s: 0.0,
        threads: 0,
    };
    let table = PyDict::new(py);
    table.set_item(
        "trial",
        run.draws.iter().map(|d| d.index).collect::<Vec<_>>(),
    )?;
    for (k, c) in spec.columns().iter().enumerate() {
        table.set_item(c, run.draws.iter().map(|d| d.values[k]).collect::<Vec<_>>())?;
    }
    table.set_item(
        "sensor_seed",
        run.draws.iter().map(|d| d.sensor_seed).collect::<Vec<_>>(),
    )?;
    let status: Vec<&str> = run.results.iter().map(TrialResult::status).collect();
    table.set_item("status", status)?;
    let failures: Vec<String> = run.results.iter().map(TrialResult::failure_list).collect();
    table.set_item("failures", failures)?;
    for (m, name) in METRICS.iter().enumerate() {
        // Undefined metrics are NaN in the table.
        let v: Vec<f64> = run
            .results
            .iter()
            .map(|r| r.metrics[m].unwrap_or(f64::NAN))
            .collect();
        table.set_item(*name, v)?;
    }
    let errors = PyList::new(py, run.results.iter().map(|r| r.error.clone()))?;
    table.set_item("error", errors)?;
    let summary = serde_json::to_string(&summary_json(&s, &spec, &run, seed))
        .map_err(|e| PyRuntimeError::new_err(format!("summary: {e}")))?;
    let summary = py.import("json")?.call_method1("loads", (summary,))?;
    Ok((table, summary))
}
