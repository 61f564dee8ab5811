//! One trial of a sweep: the scenario with its draws, run as `armdyn run` runs it (without
//! writing files), reduced to its metrics and the reasons it failed.

use serde_json::{Map, Value};

use crate::scenario::{execute, metrics_json, prepare, Outcome, Scenario};
use crate::sim::SimError;

/// The metrics of a trial, in the order of the `trials.csv` columns (SI units in the names):
/// each the number of the run's `metrics.json` ([`metrics_json`]) of the same name, except
/// `safety_trips` (the number of trips, where the file lists them) and
/// `end_stop_samples_total` (the sum of the file's `end_stop_samples`).
pub const METRICS: [&str; 23] = [
    "force_overshoot_pct",
    "settling_time_s",
    "force_rms_error_last5s_n",
    "xy_rms_error_contact_mm",
    "min_z_m",
    "normal_force_overshoot_pct",
    "normal_force_settling_time_s",
    "normal_force_rms_error_last5s_n",
    "path_rms_error_contact_mm",
    "first_touch_s",
    "force_control_start_s",
    "peak_normal_force_n",
    "contact_losses_after_first_touch",
    "max_tangential_force_n",
    "saturated_samples_total",
    "end_stop_samples_total",
    "position_rms_error_mm",
    "position_max_error_mm",
    "orientation_rms_error_deg",
    "orientation_max_error_deg",
    "safety_trips",
    "time_to_trip_s",
    "peak_normal_force_after_fault_n",
];

/// Metric `name` of [`METRICS`] from a run's `metrics.json` object `m` (`None`: not defined
/// for the run, a `null` or absent key).
fn metric(m: &Map<String, Value>, name: &str) -> Option<f64> {
    match name {
        "safety_trips" => m.get(name)?.as_array().map(|trips| trips.len() as f64),
        "end_stop_samples_total" => {
            let per_joint = m.get("end_stop_samples")?.as_array()?;
            Some(per_joint.iter().filter_map(Value::as_u64).sum::<u64>() as f64)
        }
        _ => m.get(name)?.as_f64(),
    }
}

/// Longest time any one actuator may spend saturated before a trial counts as failed for
/// saturation, s. The thesis's own hybrid trial saturates d3 for 6 ms at the force switch
/// (its 200 N step through `Kfp = 20` asks for about 4 kN): a transient of the design, not
/// a failure.
pub const SATURATION_TOLERANCE_S: f64 = 0.02;

/// Why a trial counts as failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Failure {
    /// The state became NaN or infinite (or the model could not be evaluated).
    NonFinite,
    /// The tool left the surface after first touching it.
    LostContact,
    /// An actuator saturated for more than [`SATURATION_TOLERANCE_S`].
    Saturation,
    /// A joint went past an end stop.
    EndStop,
    /// The tool's position error (after the scenario's `[metrics] after_s`) exceeded the
    /// sweep's `max_position_error_mm`.
    Tracking,
    /// The scenario with these draws could not be set up.
    Setup,
    /// The safety supervisor tripped.
    SafetyTrip,
}

impl Failure {
    /// Every reason, in report order.
    pub const ALL: [Self; 7] = [
        Self::NonFinite,
        Self::LostContact,
        Self::Saturation,
        Self::EndStop,
        Self::Tracking,
        Self::Setup,
        Self::SafetyTrip,
    ];

    /// Name in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::NonFinite => "non-finite state",
            Self::LostContact => "lost contact",
            Self::Saturation => "saturation",
            Self::EndStop => "end stop",
            Self::Tracking => "tracking",
            Self::Setup => "setup",
            Self::SafetyTrip => "safety trip",
        }
    }
}

/// What one trial gave.
#[derive(Clone, Debug, PartialEq)]
pub struct TrialResult {
    /// Each of [`METRICS`] (`None`: not defined for this trial, e.g. never settled).
    pub metrics: Vec<Option<f64>>,
    /// Why it failed (empty: it did not).
    pub failures: Vec<Failure>,
    /// The error message of a trial that could not run to its end.
    pub error: Option<String>,
}

impl TrialResult {
    /// `ok`, or `failed` for a trial with a failure: the `status` column of `trials.csv`.
    #[must_use]
    pub fn status(&self) -> &'static str {
        if self.failures.is_empty() {
            "ok"
        } else {
            "failed"
        }
    }

    /// The failures' names, `;`-separated (empty when none): the `failures` column.
    #[must_use]
    pub fn failure_list(&self) -> String {
        let names: Vec<&str> = self.failures.iter().map(|f| f.name()).collect();
        names.join(";")
    }
}

fn metrics(scenario: &Scenario, o: &Outcome) -> Vec<Option<f64>> {
    let Value::Object(m) = metrics_json(scenario, o) else {
        return vec![None; METRICS.len()];
    };
    METRICS.iter().map(|name| metric(&m, name)).collect()
}

/// A trial that could not be set up, for `error`.
#[must_use]
pub fn setup_failure(error: String) -> TrialResult {
    TrialResult {
        metrics: vec![None; METRICS.len()],
        failures: vec![Failure::Setup],
        error: Some(error),
    }
}

/// Runs `scenario` (already with its draws) and classifies it; a trial whose tool position
/// error exceeds `max_position_error_mm` (when given) fails for tracking.
#[must_use]
pub fn run_trial(scenario: &Scenario, max_position_error_mm: Option<f64>) -> TrialResult {
    let prepared = match prepare(scenario) {
        Ok(p) => p,
        Err(e) => return setup_failure(e.to_string()),
    };
    match execute(scenario, prepared, |_| {}) {
        Ok(o) => {
            let mut failures = Vec::new();
            if o.contact.as_ref().is_some_and(|c| c.contact_losses > 0) {
                failures.push(Failure::LostContact);
            }
            let dt = scenario.control_dt_s;
            if o.stats
                .saturated_samples
                .iter()
                .any(|n| *n as f64 * dt > SATURATION_TOLERANCE_S)
            {
                failures.push(Failure::Saturation);
            }
            if o.stats.end_stop_samples.iter().any(|n| *n > 0) {
                failures.push(Failure::EndStop);
            }
            if !o.safety.trips.is_empty() {
                failures.push(Failure::SafetyTrip);
            }
            if max_position_error_mm.is_some_and(|m| o.pose.position_max_m * 1e3 > m) {
                failures.push(Failure::Tracking);
            }
            TrialResult {
                metrics: metrics(scenario, &o),
                failures,
                error: None,
            }
        }
        Err(e) => TrialResult {
            metrics: vec![None; METRICS.len()],
            failures: vec![match e {
                SimError::Config(_) => Failure::Setup,
                SimError::NonFinite { .. } | SimError::Model { .. } => Failure::NonFinite,
            }],
            error: Some(e.to_string()),
        },
    }
}
