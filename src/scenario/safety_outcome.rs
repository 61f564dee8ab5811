//! What a run's safety supervisor saw, with the faults it was shown: the trips, the time from
//! the first fault to the first trip, the force after the fault, and how close the run came
//! to each limit.

use super::fault_spec::FaultSpec;
use crate::control::safety::SafetyReport;
use crate::sim::Sample;

/// One trip as reported.
#[derive(Clone, Debug, PartialEq)]
pub struct TripRecord {
    /// The cause's name (`sensor-non-finite`, `force`, ...).
    pub cause: &'static str,
    /// The joint (1-based), for a joint's cause.
    pub joint: Option<usize>,
    /// When, s.
    pub t_s: f64,
    /// The value that tripped it, in `unit`.
    pub value: f64,
    /// Its limit.
    pub limit: f64,
    /// The unit.
    pub unit: &'static str,
    /// The reaction it latched (`hold`, `retract`, `compliant`), or `latched` for a cause
    /// that crossed its limit after the first trip.
    pub reaction: &'static str,
}

/// The supervisor's summary of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct SafetySummary {
    /// The trips, the first one latching the reaction.
    pub trips: Vec<TripRecord>,
    /// The faults of the run, `(kind, start_s)`.
    pub faults: Vec<(&'static str, f64)>,
    /// First trip less the first fault's start, s.
    pub time_to_trip_s: Option<f64>,
    /// Largest true contact force (norm) from the first fault's start on, N.
    pub peak_force_after_fault_n: Option<f64>,
    /// RMS of the true force's error (`|f| - |f_d|`, force-controlled samples) over the
    /// second from the first fault's start (jitter, which runs from the start, counts only
    /// alone), N; `None` without a force-controlled sample in it.
    pub force_rms_error_after_fault_n: Option<f64>,
    /// For a surface that ends: how deep the tool was below that surface's plane (extended
    /// past the edge) at the fault's start (in the surface: the force over its stiffness),
    /// and the deepest it went after it, m.
    pub depth_below_lost_surface_m: Option<(f64, f64)>,
    /// Samples whose applied torque was not finite (always 0 with the supervisor).
    pub nan_torque_samples: usize,
    /// Samples whose torque step the supervisor slewed.
    pub torque_rate_limited_samples: u32,
    /// Readings the spike filter held back.
    pub spikes_filtered: u32,
    /// Samples whose torque was non-finite and replaced.
    pub replaced_torque_samples: u32,
    /// Force-controlled samples with an actuator saturated.
    pub saturated_force_samples: usize,
    /// Whether the force reached its reference over the run's last second (within 10 %),
    /// for a force-controlled run.
    pub force_reference_reached: Option<bool>,
    /// The report (limits and peaks), `None` without a supervisor.
    pub report: Option<ReportNumbers>,
}

/// The limits and peaks of a report, per joint as vectors.
#[derive(Clone, Debug, PartialEq)]
pub struct ReportNumbers {
    /// `(limit, peak)` of the force, N.
    pub force_n: (f64, f64),
    /// Of the force rate, N/s.
    pub force_rate_n_s: (f64, f64),
    /// Of the oscillation RMS, N (`None` limit: off).
    pub oscillation_rms_n: (Option<f64>, f64),
    /// Of the tool speed, m/s.
    pub tool_speed_m_s: (Option<f64>, f64),
    /// Largest distance outside the box, m (negative: inside).
    pub outside_workspace_m: f64,
    /// Per joint `(margin, closest approach)`.
    pub joint_limit_distance: Vec<(Option<f64>, f64)>,
    /// Per joint `(limit, peak)` speed.
    pub joint_speed: Vec<(Option<f64>, f64)>,
    /// Per joint `(limit per period, peak)` step of the applied torque.
    pub torque_step: Vec<(Option<f64>, f64)>,
}

/// Share of the force reference within which it counts as reached.
pub const REACHED_SHARE: f64 = 0.1;

/// The summary of a run of `samples` with the supervisor's `report` (if any), the
/// scenario's `faults` and control period `dt` (s).
#[must_use]
pub fn summary<const N: usize>(
    report: Option<SafetyReport<N>>,
    faults: &[FaultSpec],
    surfaces: &[crate::contact::ContactSurface],
    samples: &[Sample<N>],
    dt: f64,
) -> SafetySummary {
    // Jitter runs from the start and has no "after": the first other fault, if any.
    let first_fault = faults
        .iter()
        .filter(|f| !matches!(f, FaultSpec::Jitter(_)))
        .map(FaultSpec::start_s)
        .reduce(f64::min)
        .or_else(|| faults.first().map(FaultSpec::start_s));
    let trips: Vec<TripRecord> = report.map_or_else(Vec::new, |r| {
        r.trips
            .iter()
            .enumerate()
            .map(|(i, t)| TripRecord {
                cause: t.cause.name(),
                joint: t.cause.joint().map(|j| j + 1),
                t_s: t.t,
                value: t.value,
                limit: t.limit,
                unit: t.cause.unit(),
                reaction: if i == 0 {
                    r.limits.reaction.name()
                } else {
                    "latched"
                },
            })
            .collect()
    });
    let force = |s: &Sample<N>| s.wrench.fixed_rows::<3>(0).norm();
    let peak_force_after_fault_n = first_fault.map(|t0| {
        samples
            .iter()
            .filter(|s| s.t >= t0)
            .map(force)
            .fold(0.0, f64::max)
    });
    // None when no sample of that second was force controlled (a trip at the fault).
    let force_rms_error_after_fault_n = first_fault.and_then(|t0| {
        let e: Vec<f64> = samples
            .iter()
            .filter(|s| s.t >= t0 && s.t < t0 + 1.0 && s.force_controlled)
            .map(|s| force(s) - s.setpoint.wrench.fixed_rows::<3>(0).norm())
            .collect();
        (!e.is_empty()).then(|| libm::sqrt(e.iter().map(|x| x * x).sum::<f64>() / e.len() as f64))
    });
    let depth_below_lost_surface_m = faults.iter().find_map(|f| match *f {
        FaultSpec::SurfaceEnds { surface, start_s } => surfaces.get(surface).and_then(|g| {
            let mut after = samples.iter().filter(|s| s.t >= start_s);
            let depth = |s: &Sample<N>| -plane_distance(&g.geometry, &s.position);
            let at = depth(after.next()?);
            Some((at, after.map(depth).fold(at, f64::max)))
        }),
        _ => None,
    });
    let saturated = |s: &Sample<N>| (0..N).any(|i| s.tau[i] != s.tau_command[i]);
    let force_reference_reached = samples.iter().any(|s| s.force_controlled).then(|| {
        let end = samples.last().map_or(0.0, |s| s.t);
        let last: Vec<&Sample<N>> = samples.iter().filter(|s| s.t >= end - 1.0).collect();
        let mean = |f: &dyn Fn(&Sample<N>) -> f64| {
            last.iter().map(|s| f(s)).sum::<f64>() / last.len().max(1) as f64
        };
        let reference = mean(&|s| s.setpoint.wrench.fixed_rows::<3>(0).norm());
        (mean(&force) - reference).abs() <= REACHED_SHARE * reference
    });
    SafetySummary {
        time_to_trip_s: first_fault.zip(trips.first()).map(|(f, t)| t.t_s - f),
        trips,
        faults: faults.iter().map(|f| (f.kind(), f.start_s())).collect(),
        peak_force_after_fault_n,
        force_rms_error_after_fault_n,
        depth_below_lost_surface_m,
        nan_torque_samples: samples
            .iter()
            .filter(|s| s.tau.iter().any(|x| !x.is_finite()))
            .count(),
        torque_rate_limited_samples: report.map_or(0, |r| r.rate_limited_samples),
        spikes_filtered: report.map_or(0, |r| r.spikes_filtered),
        replaced_torque_samples: report.map_or(0, |r| r.replaced_samples),
        saturated_force_samples: samples
            .iter()
            .filter(|s| s.force_controlled && saturated(s))
            .count(),
        force_reference_reached,
        report: report.map(|r| {
            let l = r.limits;
            let p = r.peaks;
            ReportNumbers {
                force_n: (l.force.max_n, p.force_n),
                force_rate_n_s: (l.force.max_rate_n_s, r.peak_force_rate_n_s),
                oscillation_rms_n: (l.force.oscillation_rms_n, r.peak_oscillation_rms_n),
                tool_speed_m_s: (l.max_tool_speed_m_s, p.tool_speed_m_s),
                outside_workspace_m: p.outside_workspace_m,
                joint_limit_distance: (0..N)
                    .map(|i| (l.joint_margin.map(|m| m[i]), p.joint_limit_distance[i]))
                    .collect(),
                joint_speed: (0..N)
                    .map(|i| (l.max_joint_speed.map(|m| m[i]), p.joint_speed[i]))
                    .collect(),
                torque_step: (0..N)
                    .map(|i| (l.max_torque_rate.map(|m| m[i] * dt), p.torque_step[i]))
                    .collect(),
            }
        }),
    }
}

/// Signed distance of `p` from a surface, its extent ignored (a plane's patch extended).
fn plane_distance(g: &crate::contact::SurfaceGeometry, p: &nalgebra::Vector3<f64>) -> f64 {
    match g {
        crate::contact::SurfaceGeometry::Plane(plane) => plane.normal.dot(&(p - plane.point)),
        other => other.closest(p).signed_distance,
    }
}

/// A number for JSON: a non-finite value (a NaN reading that tripped) as its name.
fn number(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::json!(x)
    } else {
        serde_json::json!(format!("{x}"))
    }
}

/// Adds the summary's keys to the metrics object `obj`: `safety_trips` (cause, joint, time,
/// value, limit, unit, reaction), `faults`, `time_to_trip_s`,
/// `peak_normal_force_after_fault_n`, `nan_torque_samples`, `torque_rate_limited_samples`,
/// `spikes_filtered`, `replaced_torque_samples`, `saturated_force_samples`,
/// `force_reference_reached`, and `safety_peaks` (each checked quantity's limit and peak).
pub fn insert_json(obj: &mut serde_json::Map<String, serde_json::Value>, s: &SafetySummary) {
    use serde_json::json;
    let trips: Vec<serde_json::Value> = s
        .trips
        .iter()
        .map(|t| {
            json!({
                "cause": t.cause,
                "joint": t.joint,
                "t_s": t.t_s,
                "value": number(t.value),
                "limit": t.limit,
                "unit": t.unit,
                "reaction": t.reaction,
            })
        })
        .collect();
    let faults: Vec<serde_json::Value> = s
        .faults
        .iter()
        .map(|(kind, start)| json!({"kind": kind, "start_s": start}))
        .collect();
    let keys = json!({
        "safety_trips": trips,
        "faults": faults,
        "time_to_trip_s": s.time_to_trip_s,
        "peak_normal_force_after_fault_n": s.peak_force_after_fault_n,
        "force_rms_error_after_fault_n": s.force_rms_error_after_fault_n,
        "depth_below_lost_surface_m": s.depth_below_lost_surface_m.map(|d| d.1),
        "descent_after_surface_ends_m": s.depth_below_lost_surface_m.map(|d| d.1 - d.0),
        "nan_torque_samples": s.nan_torque_samples,
        "torque_rate_limited_samples": s.torque_rate_limited_samples,
        "spikes_filtered": s.spikes_filtered,
        "replaced_torque_samples": s.replaced_torque_samples,
        "saturated_force_samples": s.saturated_force_samples,
        "force_reference_reached": s.force_reference_reached,
    });
    if let serde_json::Value::Object(keys) = keys {
        obj.extend(keys);
    }
    if let Some(r) = &s.report {
        let pairs = |v: &[(Option<f64>, f64)]| -> Vec<serde_json::Value> {
            v.iter().map(|(a, b)| json!([a, b])).collect()
        };
        obj.insert(
            "safety_peaks".into(),
            json!({
                "force_n": [r.force_n.0, r.force_n.1],
                "force_rate_n_s": [r.force_rate_n_s.0, r.force_rate_n_s.1],
                "oscillation_rms_n": [r.oscillation_rms_n.0, r.oscillation_rms_n.1],
                "tool_speed_m_s": [r.tool_speed_m_s.0, r.tool_speed_m_s.1],
                "outside_workspace_m": r.outside_workspace_m,
                "joint_limit_distance": pairs(&r.joint_limit_distance),
                "joint_speed": pairs(&r.joint_speed),
                "torque_step": pairs(&r.torque_step),
            }),
        );
    }
}
