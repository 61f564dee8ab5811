//! `armdyn run scenario FILE... --force-law A,B,...`: every file with every force law, and
//! one table of the normal-force metrics.

use std::path::{Path, PathBuf};

use armdyn::report::Table;
use armdyn::scenario::{prepare, LawChoice, Outcome, Scenario};

use crate::run_cmd::summary::{opt, settling, write_comparison};

/// The table's columns.
const COLUMNS: [&str; 11] = [
    "scenario",
    "law",
    "overshoot (%)",
    "settling (s)",
    "tracking settling (s)",
    "RMS last 5 s (N)",
    "steady-state error (N)",
    "path RMS in contact (mm)",
    "peak force (N)",
    "saturated samples",
    "gains",
];

fn gains(r: &Outcome) -> String {
    match r.gains.force {
        Some((p, i, d)) if r.controller_name.contains("hybrid") => {
            format!("{p:.3}, {i:.3}, {d:.0}")
        }
        _ => "-".into(),
    }
}

/// Runs each of `files` with each of `laws` (checking every combination first), writes
/// each run into `out/<name>/<law>/` and `out/comparison.md`, and prints the table.
pub fn run(
    files: &[Scenario],
    laws: &[LawChoice],
    out: Option<&Path>,
    mut run_one: impl FnMut(&Scenario, &str, &Path) -> anyhow::Result<Outcome>,
) -> anyhow::Result<()> {
    let mut runs = Vec::new();
    for s in files {
        for l in laws {
            let mut s = s.clone();
            l.apply(&mut s)?;
            prepare(&s)?;
            runs.push((s, l.label()));
        }
    }
    let root = out.map_or_else(|| PathBuf::from("out/laws"), Path::to_path_buf);
    let mut rows = Vec::new();
    for (s, label) in &runs {
        let dir = root.join(&s.name).join(label.replace(':', "-"));
        let what = format!("{} {label}", s.name);
        let r = run_one(s, &what, &dir)?;
        eprintln!("wrote {}", dir.display());
        let c = r.contact.as_ref();
        let mut row = vec![
            s.name.clone(),
            label.clone(),
            opt(c.map(|c| c.normal_force_overshoot_pct), 1),
            c.map_or("-".into(), |c| settling(c.normal_force_settling_time_s)),
            c.map_or("-".into(), |c| settling(c.normal_force_tracking_settling_s)),
            opt(c.map(|c| c.normal_force_rms_error_last5s_n), 2),
            opt(c.map(|c| c.normal_force_steady_error_n), 2),
            opt(c.map(|c| c.path_rms_error_contact_mm), 2),
            opt(c.map(|c| c.peak_normal_force_n), 1),
            r.stats.saturated_samples.iter().sum::<usize>().to_string(),
            gains(&r),
        ];
        row.push(opt(r.alignment.map(|a| a.rms_deg), 4));
        row.push(opt(r.posture.map(|p| p.max_rad), 4));
        rows.push((row, r.alignment.is_some(), r.posture.is_some()));
    }
    // The tool-axis and posture columns where a run has them (an arm that controls all
    // three rotations; a redundant one).
    let with_axis = rows.iter().any(|r| r.1);
    let with_posture = rows.iter().any(|r| r.2);
    let mut headers: Vec<&str> = COLUMNS.to_vec();
    if with_axis {
        headers.push("tool axis RMS (deg)");
    }
    if with_posture {
        headers.push("posture max (rad)");
    }
    let mut table = Table::new(headers);
    for (mut row, ..) in rows {
        let posture = row.pop().unwrap_or_default();
        let axis = row.pop().unwrap_or_default();
        if with_axis {
            row.push(axis);
        }
        if with_posture {
            row.push(posture);
        }
        table.push_row(row);
    }
    write_comparison(&root, &table)
}
