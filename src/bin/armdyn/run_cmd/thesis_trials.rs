//! `armdyn run position` and `armdyn run hybrid`: the thesis's trials, one controller or all of
//! them with a comparison table.

use std::path::PathBuf;

use anyhow::Context;

use armdyn::report::{self, Table};
use armdyn::robots::scara::presets::{ForceReference, THESIS_FORCE_LAWS, THESIS_POSITION_LAWS};
use armdyn::scenario::{
    built_in, ForceController, ForceReferenceSpec, PositionController, Scenario,
};

use super::summary::{print_single, settling};
use super::{apply_sim, run_sim, HybridArgs, PositionArgs};

pub(super) fn position(a: &PositionArgs) -> anyhow::Result<()> {
    let root = a
        .sim
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out/position"));
    let list: Vec<PositionController> = match a.controller {
        Some(c) if !a.all => vec![c],
        _ => THESIS_POSITION_LAWS.to_vec(),
    };
    let mut table = Table::new([
        "controller",
        "max |e| after 2 s (q1, q2, d3, q4)",
        "RMS |e| after 2 s",
        "max |tau| (N m, N)",
    ]);
    for c in &list {
        let mut s = built_in("thesis-position.toml")?;
        s.position = *c;
        apply_sim(&mut s, &a.sim)?;
        let out = if a.all {
            root.join(c.name())
        } else {
            root.clone()
        };
        let what = format!("position {}", c.name());
        let r = run_sim(&s, &what, &out, &a.sim)?;
        if !a.all {
            print_single(&what, &r, &out);
            return Ok(());
        }
        let t = &r.tracking;
        table.push_row([
            c.name().to_string(),
            join(&t.max_joint_error_after, |x| format!("{x:.2e}")),
            join(&t.rms_joint_error_after, |x| format!("{x:.2e}")),
            join(&t.max_abs_tau, |x| format!("{x:.1}")),
        ]);
        eprintln!("wrote {}", out.display());
    }
    let md = table.markdown();
    outln!("Position test (eq. 4.16), errors in rad or m:\n\n{md}");
    report::write_atomic(root.join("comparison.md"), &md)?;
    outln!("comparison table: {}", root.join("comparison.md").display());
    Ok(())
}

/// The built-in hybrid scenario with the trial's command-line choices.
pub(super) fn hybrid_scenario(
    a: &HybridArgs,
    f: ForceController,
    r: ForceReference,
) -> anyhow::Result<Scenario> {
    let mut s = built_in("thesis-hybrid.toml")?;
    apply_sim(&mut s, &a.sim)?;
    let force = s
        .force
        .as_mut()
        .context("the built-in hybrid scenario has a [force] table")?;
    force.law = f;
    force.gains = f.thesis_gains();
    force.reference = match r {
        ForceReference::Const => ForceReferenceSpec::Constant,
        ForceReference::Var => ForceReferenceSpec::ThesisVariable,
    };
    s.sensor.noise_n = a.sensor_noise;
    s.sensor.bias_n = a.sensor_bias;
    s.sensor.cutoff_hz = a.sensor_cutoff;
    s.sensor.seed = a.seed;
    Ok(s)
}

/// `armdyn run hybrid` (and the default command).
pub fn hybrid(a: &HybridArgs) -> anyhow::Result<()> {
    let root = a
        .sim
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out/hybrid"));
    let combos: Vec<(ForceController, ForceReference)> = if a.all {
        THESIS_FORCE_LAWS
            .iter()
            .flat_map(|f| ForceReference::ALL.iter().map(move |r| (*f, *r)))
            .collect()
    } else {
        vec![(a.force_controller, a.force)]
    };
    let mut table = Table::new([
        "force law",
        "force",
        "overshoot (%)",
        "settling (s)",
        "RMS force error, last 5 s (N)",
        "x-y RMS error in contact (mm)",
        "min z (m)",
        "safety",
    ]);
    for (f, r) in &combos {
        let s = hybrid_scenario(a, *f, *r)?;
        let out = if a.all {
            root.join(format!("{}-{}", f.name(), r.name()))
        } else {
            root.clone()
        };
        let what = format!("hybrid {} {}", f.name(), r.name());
        let result = run_sim(&s, &what, &out, &a.sim)?;
        let fm = result
            .force
            .as_ref()
            .context("hybrid runs have force metrics")?;
        table.push_row([
            f.name().to_string(),
            r.name().to_string(),
            format!("{:.1}", fm.force_overshoot_pct),
            settling(fm.settling_time_s),
            format!("{:.2}", fm.force_rms_error_last_n),
            format!("{:.2}", fm.xy_rms_error_contact_mm),
            format!("{:.4}", fm.min_z_m),
            safety_cell(&s, &result),
        ]);
        if !a.all {
            print_single(&what, &result, &out);
            return Ok(());
        }
        eprintln!("wrote {}", out.display());
    }
    let md = table.markdown();
    outln!(
        "Hybrid force/position trial (contact reference B.3, surface z = 0.13 m, 10 kN/m):\n\n{md}"
    );
    report::write_atomic(root.join("comparison.md"), &md)?;
    outln!("comparison table: {}", root.join("comparison.md").display());
    Ok(())
}

/// The table's safety cell: the first trip (cause, time, reaction), `no trip`, or `off`.
fn safety_cell(s: &Scenario, result: &armdyn::scenario::Outcome) -> String {
    if !s.safety.enabled {
        return "off".into();
    }
    result.safety.trips.first().map_or("no trip".into(), |t| {
        format!("{} at {:.3} s, {}", t.cause, t.t_s, t.reaction)
    })
}

fn join(v: &[f64], format: impl Fn(f64) -> String) -> String {
    v.iter().map(|x| format(*x)).collect::<Vec<_>>().join(", ")
}
