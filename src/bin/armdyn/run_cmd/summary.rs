//! What one run prints: joint tracking, tool pose, force and contact metrics, and where its
//! files are.

use std::path::Path;

use armdyn::report::{self, Table};
use armdyn::scenario::{output_names, Outcome};

pub(super) fn print_single(what: &str, r: &Outcome, dir: &Path) {
    let t = &r.tracking;
    let mut table = Table::new(std::iter::once("metric").chain(r.joint_names.iter().copied()));
    let row = |name: &str, v: &[f64]| {
        std::iter::once(name.to_string())
            .chain(v.iter().map(|x| format!("{x:.3e}")))
            .collect::<Vec<_>>()
    };
    table.push_row(row("RMS error (rad, m)", &t.rms_joint_error));
    table.push_row(row("RMS error after 2 s", &t.rms_joint_error_after));
    table.push_row(row("max |error| after 2 s", &t.max_joint_error_after));
    table.push_row(row("max |tau| (N m, N)", &t.max_abs_tau));
    outln!(
        "{what} ({} samples)\n\n{}",
        r.stats.samples,
        table.markdown()
    );
    outln!(
        "tool pose after {} s, in the task {}: position RMS {:.4} mm (max {:.4} mm), orientation RMS {:.4} degrees (max {:.4} degrees)",
        r.pose.after_s,
        r.task.names().join(", "),
        r.pose.position_rms_m * 1e3,
        r.pose.position_max_m * 1e3,
        r.pose.orientation_rms_rad.to_degrees(),
        r.pose.orientation_max_rad.to_degrees()
    );
    if let Some(f) = &r.force {
        let mut ft = Table::new(["force metric", "value"]);
        let mut push = |k: &str, v: String| ft.push_row([k.to_string(), v]);
        push(
            "overshoot beyond the reference after the switch (% of the nominal force)",
            format!("{:.2}", f.force_overshoot_pct),
        );
        push(
            "settling time after the switch, 5 % band (s)",
            settling(f.settling_time_s),
        );
        push(
            "RMS force error, last 5 s (N)",
            format!("{:.3}", f.force_rms_error_last_n),
        );
        push(
            "x-y RMS error in contact (mm)",
            format!("{:.3}", f.xy_rms_error_contact_mm),
        );
        push("lowest tool z (m)", format!("{:.4}", f.min_z_m));
        if let Some(c) = &r.contact {
            push(
                "normal force overshoot (%)",
                format!("{:.2}", c.normal_force_overshoot_pct),
            );
            push(
                "normal force settling, 5 % band (s)",
                settling(c.normal_force_settling_time_s),
            );
            push(
                "normal force RMS error, last 5 s (N)",
                format!("{:.3}", c.normal_force_rms_error_last5s_n),
            );
            push(
                "tangential path RMS error in contact (mm)",
                format!("{:.3}", c.path_rms_error_contact_mm),
            );
            push("first touch (s)", opt(c.first_touch_s, 3));
            push("force control from (s)", opt(c.force_start_s, 3));
            push(
                "peak normal force (N)",
                format!("{:.1}", c.peak_normal_force_n),
            );
            push(
                "max tangential force (N)",
                format!("{:.1}", c.max_tangential_force_n),
            );
        }
        outln!("{}", ft.markdown());
    }
    let stats = &r.stats;
    let sat: usize = stats.saturated_samples.iter().sum();
    let stops: usize = stats.end_stop_samples.iter().sum();
    if sat > 0 || stops > 0 {
        outln!("saturated samples: {sat}; samples past an end stop: {stops}");
    }
    if r.joint_limit_violation_samples > 0 {
        outln!(
            "samples with a joint outside its limits: {}",
            r.joint_limit_violation_samples
        );
    }
    for note in &r.reference.notes {
        outln!("{note}");
    }
    print_safety(&r.safety);
    let view = dir.join("view.html").is_file();
    outln!("wrote {}/: {}", dir.display(), output_names(r, view));
}

/// The faults of the run and the supervisor's trips, one line each (nothing for a run
/// without faults or trips).
fn print_safety(s: &armdyn::scenario::safety_outcome::SafetySummary) {
    for (kind, start) in &s.faults {
        outln!("fault: {kind} from {start:.3} s");
    }
    for (i, t) in s.trips.iter().enumerate() {
        // 1-based already.
        let joint = t.joint.map_or(String::new(), |j| format!(" (joint {j})"));
        outln!(
            "safety trip{}: {}{joint} at {:.3} s, {} against the limit {} {}; {}",
            if i == 0 { "" } else { " (while latched)" },
            t.cause,
            t.t_s,
            t.value,
            t.limit,
            t.unit,
            t.reaction
        );
    }
    if let Some(dt) = s.time_to_trip_s {
        outln!("time from the first fault to the trip: {dt:.3} s");
    }
    if s.torque_rate_limited_samples > 0 || s.spikes_filtered > 0 {
        outln!(
            "torque steps slewed: {}; spikes filtered: {}",
            s.torque_rate_limited_samples,
            s.spikes_filtered
        );
    }
}

/// `v` with `digits` decimals, or `-`.
pub(crate) fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or("-".into(), |x| format!("{x:.digits$}"))
}

/// A settling time `t` in s with 3 decimals, or `not settled`.
pub(crate) fn settling(t: Option<f64>) -> String {
    t.map_or("not settled".into(), |t| format!("{t:.3}"))
}

/// A table of several runs: printed, and written as `root/comparison.md` (whole or not at
/// all).
///
/// # Errors
///
/// If the file cannot be written.
pub(crate) fn write_comparison(root: &Path, table: &Table) -> anyhow::Result<()> {
    let md = table.markdown();
    outln!("{md}");
    let path = root.join("comparison.md");
    report::write_atomic(&path, &md)?;
    outln!("comparison table: {}", path.display());
    Ok(())
}
