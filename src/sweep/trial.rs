//! One trial of a sweep: the scenario with its draws, run as `armdyn run` runs it (without
//! writing files), reduced to its metrics and the reasons it failed.

use crate::metrics::{ContactSummary, ForceSummary};
use crate::scenario::{execute, prepare, Outcome, Scenario};
use crate::sim::SimError;

/// A metric of a run's outcome (`None`: not defined for it).
type Metric = fn(&Outcome) -> Option<f64>;

/// Each metric of a trial with its name, in the order of the `trials.csv` columns (SI units
/// in the names); `None`: not defined for this trial (e.g. never settled).
const COLUMNS: [(&str, Metric); 23] = [
    ("force_overshoot_pct", |o| {
        force(o).map(|f| f.force_overshoot_pct)
    }),
    ("settling_time_s", |o| {
        force(o).and_then(|f| f.settling_time_s)
    }),
    ("force_rms_error_last5s_n", |o| {
        force(o).map(|f| f.force_rms_error_last_n)
    }),
    ("xy_rms_error_contact_mm", |o| {
        force(o).map(|f| f.xy_rms_error_contact_mm)
    }),
    ("min_z_m", |o| force(o).map(|f| f.min_z_m)),
    ("normal_force_overshoot_pct", |o| {
        contact(o).map(|c| c.normal_force_overshoot_pct)
    }),
    ("normal_force_settling_time_s", |o| {
        contact(o).and_then(|c| c.normal_force_settling_time_s)
    }),
    ("normal_force_rms_error_last5s_n", |o| {
        contact(o).map(|c| c.normal_force_rms_error_last5s_n)
    }),
    ("path_rms_error_contact_mm", |o| {
        contact(o).map(|c| c.path_rms_error_contact_mm)
    }),
    ("first_touch_s", |o| {
        contact(o).and_then(|c| c.first_touch_s)
    }),
    ("force_control_start_s", |o| {
        contact(o).and_then(|c| c.force_start_s)
    }),
    ("peak_normal_force_n", |o| {
        contact(o).map(|c| c.peak_normal_force_n)
    }),
    ("contact_losses_after_first_touch", |o| {
        contact(o).map(|c| c.contact_losses as f64)
    }),
    ("max_tangential_force_n", |o| {
        contact(o).map(|c| c.max_tangential_force_n)
    }),
    ("saturated_samples_total", |o| {
        Some(o.stats.saturated_samples.iter().sum::<usize>() as f64)
    }),
    ("end_stop_samples_total", |o| {
        Some(o.stats.end_stop_samples.iter().sum::<usize>() as f64)
    }),
    ("position_rms_error_mm", |o| {
        Some(o.pose.position_rms_m * 1e3)
    }),
    ("position_max_error_mm", |o| {
        Some(o.pose.position_max_m * 1e3)
    }),
    ("orientation_rms_error_deg", |o| {
        Some(o.pose.orientation_rms_rad.to_degrees())
    }),
    ("orientation_max_error_deg", |o| {
        Some(o.pose.orientation_max_rad.to_degrees())
    }),
    ("safety_trips", |o| Some(o.safety.trips.len() as f64)),
    ("time_to_trip_s", |o| o.safety.time_to_trip_s),
    ("peak_normal_force_after_fault_n", |o| {
        o.safety.peak_force_after_fault_n
    }),
];

fn force(o: &Outcome) -> Option<&ForceSummary> {
    o.force.as_ref()
}

fn contact(o: &Outcome) -> Option<&ContactSummary> {
    o.contact.as_ref()
}

/// The metrics' names, in the order of the `trials.csv` columns (each read from a run's
/// outcome by the function paired with it in this module's table of columns).
pub const METRICS: [&str; 23] = {
    let mut names = [""; 23];
    let mut i = 0;
    while i < names.len() {
        names[i] = COLUMNS[i].0;
        i += 1;
    }
    names
};

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

fn metrics(o: &Outcome) -> Vec<Option<f64>> {
    COLUMNS.iter().map(|(_, value)| value(o)).collect()
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
            if contact(&o).is_some_and(|c| c.contact_losses > 0) {
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
                metrics: metrics(&o),
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
