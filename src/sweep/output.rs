//! What a sweep writes: `trials.csv` (one row per trial: draws, status, every metric),
//! `summary.json` (percentiles per metric, failures and their reasons) and histograms.

use std::collections::BTreeMap;
use std::path::Path;

use serde_json::{json, Map, Value};

use super::run::SweepRun;
use super::spec::SweepSpec;
use super::trial::{Failure, METRICS};
use crate::report::data_plots::histogram;
use crate::report::OutputDir;
use crate::scenario::Scenario;

/// Metrics drawn as histograms (where at least one trial defines them).
pub const HISTOGRAMS: [&str; 7] = [
    "normal_force_overshoot_pct",
    "normal_force_settling_time_s",
    "normal_force_rms_error_last5s_n",
    "path_rms_error_contact_mm",
    "peak_normal_force_n",
    "position_max_error_mm",
    "orientation_max_error_deg",
];

fn number(x: Option<f64>) -> String {
    x.map_or(String::new(), |v| format!("{v}"))
}

/// `trials.csv`: `trial`, the drawn columns, `sensor_seed`, `status` (`ok` or `failed`),
/// `failures` (`;`-separated reasons), every metric, `error`. Numbers are written in their
/// shortest exact form, so the text depends only on the values.
///
/// # Errors
///
/// If the CSV writer fails (not for in-memory output).
pub fn trials_csv(spec: &SweepSpec, run: &SweepRun) -> Result<String, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["trial".to_string()];
    header.extend(spec.columns());
    header.extend(["sensor_seed", "status", "failures"].map(String::from));
    header.extend(METRICS.map(String::from));
    header.push("error".into());
    w.write_record(&header)?;
    for (d, r) in run.draws.iter().zip(&run.results) {
        let mut row = vec![d.index.to_string()];
        row.extend(d.values.iter().map(|v| format!("{v}")));
        row.push(d.sensor_seed.to_string());
        row.push(r.status().into());
        row.push(r.failure_list());
        row.extend(r.metrics.iter().map(|m| number(*m)));
        row.push(r.error.clone().unwrap_or_default());
        w.write_record(&row)?;
    }
    let bytes = w.into_inner().map_err(|e| e.into_error())?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// Percentile `p` (0 to 100) of sorted `v` by linear interpolation between order statistics.
#[must_use]
pub fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let x = p / 100.0 * (sorted.len() - 1) as f64;
    let (i, f) = (x.floor() as usize, x - x.floor());
    let j = (i + 1).min(sorted.len() - 1);
    sorted[i] + f * (sorted[j] - sorted[i])
}

fn values(run: &SweepRun, m: usize) -> Vec<f64> {
    let mut v: Vec<f64> = run
        .results
        .iter()
        .filter_map(|r| r.metrics[m])
        .filter(|x| x.is_finite())
        .collect();
    v.sort_by(f64::total_cmp);
    v
}

/// One metric over the trials that have it (finite): how many, its 5th, 50th and 95th
/// percentiles and its largest value (`None`: no trial has it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MetricSummary {
    /// The metric's name ([`METRICS`]).
    pub name: &'static str,
    /// Trials with a finite value.
    pub count: usize,
    /// `(p5, p50, p95, max)`, `None` when `count` is 0.
    pub spread: Option<(f64, f64, f64, f64)>,
}

/// Every metric of [`METRICS`] summarised over the run's trials: what `summary.json` and
/// the command's table show.
#[must_use]
pub fn summarise(run: &SweepRun) -> Vec<MetricSummary> {
    METRICS
        .iter()
        .enumerate()
        .map(|(m, name)| {
            let v = values(run, m);
            MetricSummary {
                name,
                count: v.len(),
                spread: (!v.is_empty()).then(|| {
                    (
                        percentile(&v, 5.0),
                        percentile(&v, 50.0),
                        percentile(&v, 95.0),
                        v[v.len() - 1],
                    )
                }),
            }
        })
        .collect()
}

/// The failed trials of a run: how many, and for each reason of [`Failure::ALL`] (in its
/// order) the numbers of the trials that failed for it: what `summary.json` and the command's
/// line of failures show.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FailureSummary {
    /// Trials with at least one failure.
    pub failed: usize,
    /// Each reason with the numbers of the trials ([`Draw::index`](super::Draw::index)) it failed.
    pub by_reason: Vec<(Failure, Vec<usize>)>,
}

/// The run's [`FailureSummary`].
#[must_use]
pub fn failures(run: &SweepRun) -> FailureSummary {
    let mut by_reason: Vec<(Failure, Vec<usize>)> =
        Failure::ALL.iter().map(|&f| (f, Vec::new())).collect();
    for (d, r) in run.draws.iter().zip(&run.results) {
        for f in &r.failures {
            if let Some((_, trials)) = by_reason.iter_mut().find(|(g, _)| g == f) {
                trials.push(d.index);
            }
        }
    }
    FailureSummary {
        failed: run
            .results
            .iter()
            .filter(|r| !r.failures.is_empty())
            .count(),
        by_reason,
    }
}

/// `summary.json` (its failure reasons in the order of their names).
#[must_use]
pub fn summary_json(scenario: &Scenario, spec: &SweepSpec, run: &SweepRun, seed: u64) -> Value {
    let mut metrics = Map::new();
    for m in summarise(run) {
        metrics.insert(
            m.name.into(),
            match m.spread {
                None => json!({"count": 0}),
                Some((p5, p50, p95, max)) => json!({
                    "count": m.count,
                    "p5": p5,
                    "p50": p50,
                    "p95": p95,
                    "max": max,
                }),
            },
        );
    }
    let FailureSummary { failed, by_reason } = failures(run);
    let reasons: BTreeMap<&str, Vec<usize>> =
        by_reason.into_iter().map(|(f, v)| (f.name(), v)).collect();
    let columns = spec.columns();
    let drawn: Map<String, Value> = columns
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let (lo, hi) = run
                .draws
                .iter()
                .map(|d| d.values[k])
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                    (l.min(x), h.max(x))
                });
            (c.clone(), json!({"min": lo, "max": hi}))
        })
        .collect();
    json!({
        "scenario": scenario.name,
        "file": scenario.file,
        "samples": run.results.len(),
        "seed": seed,
        "percentiles": "over the trials that define the metric (failed ones included), linear interpolation between order statistics",
        "metrics": metrics,
        "failed_trials": failed,
        "failure_reasons": reasons.iter().map(|(k, v)| (k.to_string(), json!(v.len()))).collect::<Map<String, Value>>(),
        "failed_trial_numbers": reasons.iter().filter(|(_, v)| !v.is_empty()).map(|(k, v)| (k.to_string(), json!(v.iter().take(20).collect::<Vec<_>>()))).collect::<Map<String, Value>>(),
        "drawn": drawn,
    })
}

/// Writes `trials.csv`, `summary.json` and the histograms into `dir`, all or nothing.
///
/// # Errors
///
/// If a file cannot be written or a figure drawn (nothing is left behind).
pub fn write_sweep(
    dir: &Path,
    scenario: &Scenario,
    spec: &SweepSpec,
    run: &SweepRun,
    seed: u64,
) -> anyhow::Result<Vec<String>> {
    use anyhow::Context;
    let mut out =
        OutputDir::create(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let mut names = vec!["trials.csv".to_string(), "summary.json".to_string()];
    out.write("trials.csv", trials_csv(spec, run)?)?;
    out.write(
        "summary.json",
        serde_json::to_string_pretty(&summary_json(scenario, spec, run, seed))? + "\n",
    )?;
    for name in HISTOGRAMS {
        let Some(m) = METRICS.iter().position(|x| *x == name) else {
            continue;
        };
        let v = values(run, m);
        if v.is_empty() {
            continue;
        }
        let file = format!("histogram_{name}.svg");
        out.write(
            &file,
            histogram(
                &format!("{}: {name} over {} trials", scenario.name, v.len()),
                name,
                &v,
                30,
            )?,
        )?;
        names.push(file);
    }
    out.commit()
        .with_context(|| format!("cannot write into {}", dir.display()))?;
    Ok(names)
}

#[cfg(test)]
mod tests {
    use super::percentile;

    #[test]
    fn percentiles_interpolate() {
        let v = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(percentile(&v, 50.0), 3.0);
        assert_eq!(percentile(&v, 100.0), 5.0);
        approx::assert_relative_eq!(percentile(&v, 5.0), 1.2);
        assert!(percentile(&[], 5.0).is_nan());
    }
}
