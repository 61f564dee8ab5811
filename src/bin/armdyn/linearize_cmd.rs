//! `armdyn design linearize`: a scenario's sampled closed loop linearised at a time of its
//! run; its discrete eigenvalues, the slowest and the least damped modes and the states they
//! live in.

use std::path::PathBuf;

use clap::Args;
use serde_json::json;

use armdyn::scenario::linearize::{linearize, linearize_equilibrium, nominal};
use armdyn::scenario::Scenario;
use armdyn::sim::linearize::{Mode, Modes, MODE_WINDOW_S};

use crate::json_out::to_json;

/// Arguments of `armdyn design linearize`.
#[derive(Debug, Args)]
pub struct LinearizeArgs {
    /// The scenario file.
    #[arg(long, value_name = "FILE")]
    scenario: PathBuf,
    /// Time of the run to linearise at, s (the first control sample at or after it).
    #[arg(long, allow_hyphen_values = true, value_name = "S")]
    at: f64,
    /// Linearise at the loop's equilibrium nearest the run's state at `--at` (the reference
    /// held there; it must be at rest), not at the run's state itself: the rest point a run
    /// that oscillates or slides never samples.
    #[arg(long)]
    equilibrium: bool,
    /// Print one JSON object.
    #[arg(long)]
    json: bool,
}

fn mode_json(m: &Mode) -> serde_json::Value {
    json!({
        "z": [m.z.re, m.z.im],
        "magnitude": m.magnitude,
        "s": [m.s.re, m.s.im],
        "frequency_hz": m.frequency_hz,
        "damping_ratio": m.damping_ratio,
        "time_constant_s": m.time_constant_s,
        "neutral": m.is_neutral(),
        "states": m.states.iter().map(|(l, p)| json!([l, p])).collect::<Vec<_>>(),
    })
}

/// The `k` states with the largest shares of the mode, as `label share %, ...`.
fn leading_states(m: &Mode, k: usize) -> String {
    m.states
        .iter()
        .take(k)
        .map(|(l, p)| format!("{l} {:.0} %", 100.0 * p))
        .collect::<Vec<_>>()
        .join(", ")
}

fn describe(m: &Mode) -> String {
    let states = leading_states(m, 4);
    format!(
        "z = {:.6}{:+.6}i, |z| = {:.6}, {:.3} Hz, damping {:.3}; in {}",
        m.z.re, m.z.im, m.magnitude, m.frequency_hz, m.damping_ratio, states
    )
}

/// Runs `armdyn design linearize`.
pub fn run(a: &LinearizeArgs) -> anyhow::Result<()> {
    let scenario = Scenario::load(&a.scenario)?;
    let changed = nominal(&scenario) != scenario;
    let lin = if a.equilibrium {
        linearize_equilibrium(&scenario, a.at)?
    } else {
        linearize(&scenario, a.at)?
    };
    let modes = Modes::of(&lin.a, lin.dt, &lin.labels);
    if a.json {
        let value = json!({
            "scenario": a.scenario.display().to_string(),
            "t_s": lin.t,
            "dt_s": lin.dt,
            "q": lin.q,
            "qd": lin.qd,
            "tau": lin.tau,
            "states": lin.labels,
            "stable": modes.stable(),
            "mode_exits_last_s": lin.mode_exits,
            "settles": lin.settles(),
            "next_state_mismatch": lin.next_state_mismatch,
            "equilibrium": lin.equilibrium.as_ref().map(|e| json!({
                "newton_iterations": e.iterations,
                "relative_residual": e.residual,
                "joint_distance_from_run": e.joint_distance,
                "run_joint_speed": e.run_joint_speed,
            })),
            "without_noise_and_faults": changed,
            "slowest": modes.slowest().map(mode_json),
            "least_damped": modes.least_damped().map(mode_json),
            "modes": modes.modes.iter().map(mode_json).collect::<Vec<_>>(),
        });
        outln!("{}", to_json(&value, false));
        return Ok(());
    }
    outln!(
        "{} linearised at t = {:.4} s (control period {} s, {} states){}",
        a.scenario.display(),
        lin.t,
        lin.dt,
        lin.labels.len(),
        if changed {
            "; sensor noise and injected faults left out"
        } else {
            ""
        }
    );
    let fmt = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:.4}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if let Some(e) = &lin.equilibrium {
        outln!(
            "  at the equilibrium nearest the run's state (Newton: {} iterations, relative \
             residual {:.1e}; joints {:.2e} from the run's, which moved at up to {:.2e})",
            e.iterations,
            e.residual,
            e.joint_distance,
            e.run_joint_speed
        );
    }
    outln!("  q = [{}], qd = [{}]", fmt(&lin.q), fmt(&lin.qd));
    outln!("  tau = [{}]", fmt(&lin.tau));
    outln!(
        "  the linearised map's plant reproduces the run's next sample to {:.1e}",
        lin.next_state_mismatch
    );
    outln!("discrete eigenvalues (by |z|):");
    outln!(
        "  {:>12} {:>12} {:>10} {:>10} {:>8}  states",
        "Re z",
        "Im z",
        "|z|",
        "Hz",
        "damping"
    );
    for m in &modes.modes {
        let states = leading_states(m, 3);
        outln!(
            "  {:>12.6} {:>12.6} {:>10.6} {:>10.3} {:>8.3}  {}{}",
            m.z.re,
            m.z.im,
            m.magnitude,
            m.frequency_hz,
            m.damping_ratio,
            states,
            if m.is_neutral() { " (neutral)" } else { "" }
        );
    }
    if let Some(m) = modes.slowest() {
        outln!("slowest mode: {}", describe(m));
    }
    if let Some(m) = modes.least_damped() {
        outln!("least damped mode: {}", describe(m));
    }
    outln!(
        "{}",
        if modes.stable() {
            "stable: every mode decays (neutral modes at z = 1 excepted)"
        } else {
            "UNSTABLE: a mode grows (|z| > 1)"
        }
    );
    if lin.mode_exits > 0 {
        outln!(
            "SWITCHING: the run left {} control {} times in the {} s up to this sample: a cycle \
             through the contact selection's switch, which a linearisation of one mode does not \
             describe; the run does not settle",
            if lin.force_controlled {
                "force"
            } else {
                "position"
            },
            lin.mode_exits,
            MODE_WINDOW_S
        );
    }
    Ok(())
}
