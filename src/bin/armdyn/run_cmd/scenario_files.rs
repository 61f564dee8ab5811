//! `armdyn run scenario FILE...`: scenario files, one or several (a comparison table), or
//! one or several with each of several force laws.

use std::path::PathBuf;

use armdyn::report::Table;
use armdyn::scenario::{Outcome, Scenario};

use super::summary::{opt, print_single, settling, write_comparison};
use super::{controller_model, run_one, ScenarioArgs};

pub(super) fn scenarios(a: &ScenarioArgs) -> anyhow::Result<()> {
    // Every file is read and checked before anything runs.
    let mut list = Vec::new();
    for f in &a.files {
        // A sweep's table is the sweep's: `armdyn run` runs the nominal scenario.
        let mut s = Scenario::load_with(f, &[armdyn::sweep::TABLE])?;
        if a.no_safety {
            s.safety.enabled = false;
        }
        if let Some(m) = &a.controller_model {
            s.controller_model = controller_model(&s, m)?;
        }
        if let [one] = a.force_law.as_slice() {
            one.apply(&mut s)?;
        }
        a.limit.check_scenario(&s.name, &s)?;
        a.precision.prepare(&s)?;
        list.push(s);
    }
    if a.force_law.len() > 1 && !a.check {
        return crate::law_table::run(&list, &a.force_law, a.out.as_deref(), |s, what, out| {
            run_one(s, what, out, &a.limit, a.precision, !a.no_view)
        });
    }
    if a.check {
        for s in &list {
            outln!("{}: ok ({})", s.file, s.name);
        }
        return Ok(());
    }
    if list.len() == 1 {
        let s = &list[0];
        let out = a
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from(format!("out/{}", s.name)));
        let r = run_one(s, &s.name, &out, &a.limit, a.precision, !a.no_view)?;
        print_single(&s.name, &r, &out);
        return Ok(());
    }
    let root = a
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out/scenarios"));
    let mut table = Table::new([
        "scenario",
        "selection",
        "overshoot (%)",
        "settling (s)",
        "RMS force error, last 5 s (N)",
        "path RMS in contact (mm)",
        "first touch (s)",
        "contact detected (s)",
        "peak normal force (N)",
        "max tangential force (N)",
        "saturated samples",
        "end-stop samples",
    ]);
    for s in &list {
        let out = root.join(&s.name);
        let r = run_one(s, &s.name, &out, &a.limit, a.precision, !a.no_view)?;
        eprintln!("wrote {}", out.display());
        table.push_row(summary_row(s, &r));
    }
    write_comparison(&root, &table)
}

pub(super) fn summary_row(s: &Scenario, r: &Outcome) -> Vec<String> {
    let c = r.contact.as_ref();
    let stats = &r.stats;
    vec![
        s.name.clone(),
        r.selection.unwrap_or("-").to_string(),
        opt(
            c.filter(|_| s.force.is_some())
                .map(|c| c.normal_force_overshoot_pct),
            1,
        ),
        c.filter(|_| s.force.is_some())
            .map_or("-".into(), |c| settling(c.normal_force_settling_time_s)),
        opt(
            c.filter(|_| s.force.is_some())
                .map(|c| c.normal_force_rms_error_last5s_n),
            2,
        ),
        opt(
            c.filter(|_| s.force.is_some())
                .map(|c| c.path_rms_error_contact_mm),
            2,
        ),
        opt(c.and_then(|c| c.first_touch_s), 3),
        opt(
            c.and_then(|c| c.force_start_s)
                .filter(|_| r.selection == Some("contact")),
            3,
        ),
        opt(c.map(|c| c.peak_normal_force_n), 1),
        opt(c.map(|c| c.max_tangential_force_n), 1),
        stats.saturated_samples.iter().sum::<usize>().to_string(),
        stats.end_stop_samples.iter().sum::<usize>().to_string(),
    ]
}
