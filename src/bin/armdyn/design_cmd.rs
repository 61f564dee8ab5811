//! `armdyn design force`: gains for the force loop along the contact normal by discrete
//! pole placement, or the analysis of given gains: poles, margins, the stiffness range.

use std::path::PathBuf;

use anyhow::{bail, Context};
use clap::{Args, Subcommand};
use serde_json::json;

use armdyn::control::design::{
    analyse, bang_bang_settling, default_sweep, design, Analysis, DesignSpec, ForceGains,
    ForceLoop, PushLimit, MIN_DAMPING_RATIO,
};
use armdyn::scenario::{contact_model, Scenario};

use crate::cli_args::{parse_number_list, NumberList};
use crate::json_out::to_json;

/// Arguments of `armdyn design`.
#[derive(Debug, Args)]
pub struct DesignArgs {
    #[command(subcommand)]
    what: What,
}

#[derive(Debug, Subcommand)]
enum What {
    /// The force loop along the contact normal: PI + feedforward + velocity damping.
    Force(ForceArgs),
    /// A scenario's sampled closed loop linearised at a time of its run: eigenvalues and modes.
    Linearize(crate::linearize_cmd::LinearizeArgs),
}

#[derive(Debug, Args)]
struct ForceArgs {
    /// Contact stiffness, N/m (default with --scenario: its force surface's).
    #[arg(long, allow_hyphen_values = true, value_name = "N/m")]
    k: Option<f64>,
    /// Contact damping, N s/m (default 0, or the scenario surface's).
    #[arg(long, allow_hyphen_values = true, value_name = "N s/m")]
    contact_damping: Option<f64>,
    /// Controller period, s (default with --scenario: its control_dt_s).
    #[arg(long, allow_hyphen_values = true, value_name = "S")]
    dt: Option<f64>,
    /// Apparent mass of the robot along the normal, kg.
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "KG",
        conflicts_with = "scenario"
    )]
    mass: Option<f64>,
    /// Take the apparent mass at a scenario's contact pose (and its stiffness and period).
    #[arg(long, value_name = "FILE")]
    scenario: Option<PathBuf>,
    /// Natural frequency of the dominant closed-loop pair, Hz.
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "F",
        required_unless_present = "evaluate"
    )]
    bandwidth_hz: Option<f64>,
    /// Its damping ratio.
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "Z",
        required_unless_present = "evaluate"
    )]
    damping: Option<f64>,
    /// The integral pole, Hz (default: a hundredth of the bandwidth).
    #[arg(long, value_name = "F")]
    integral_hz: Option<f64>,
    /// Model one period of computation delay.
    #[arg(long)]
    delay: bool,
    /// Analyse these gains instead of designing: kfp,kfi,kvd.
    #[arg(long, allow_hyphen_values = true, value_name = "KFP,KFI,KVD", value_parser = parse_number_list, conflicts_with_all = ["bandwidth_hz", "damping", "integral_hz"])]
    evaluate: Option<NumberList>,
    /// Stiffness sweep for the stable range, N/m: lo,hi (default k/10,1000k).
    #[arg(long, value_name = "LO,HI", value_parser = parse_number_list)]
    k_sweep: Option<NumberList>,
    /// Print one JSON object.
    #[arg(long)]
    json: bool,
}

/// Runs `armdyn design ...`.
pub fn run(args: &DesignArgs) -> anyhow::Result<()> {
    match &args.what {
        What::Force(a) => force(a),
        What::Linearize(a) => crate::linearize_cmd::run(a),
    }
}

fn force(a: &ForceArgs) -> anyhow::Result<()> {
    let mut actuator = None;
    let (mass, k, c, dt, source) =
        match (&a.scenario, a.mass) {
            (Some(file), _) => {
                let s = Scenario::load(file)?;
                let m = contact_model(&s)?;
                let k = a.k.unwrap_or(m.stiffness);
                if let Some(f) = &s.force {
                    let limit = m.push_limit()?;
                    actuator = Some(ActuatorBound {
                        limit,
                        target_n: f.value_n,
                        stiffness: k,
                        settling_s: bang_bang_settling(&limit, k, 0.0, f.value_n),
                    });
                }
                (
                    m.mass_kg,
                    k,
                    a.contact_damping.unwrap_or(m.damping),
                    a.dt.unwrap_or(s.control_dt_s),
                    format!(
                    "{} at its contact pose (t = {:.3} s, q = [{}], normal [{:.3}, {:.3}, {:.3}])",
                    file.display(),
                    m.t_s,
                    m.q.iter().map(|x| format!("{x:.4}")).collect::<Vec<_>>().join(", "),
                    m.normal.x,
                    m.normal.y,
                    m.normal.z
                ),
                )
            }
            (None, Some(mass)) => (
                mass,
                a.k.context("--k N/m is needed (or --scenario FILE)")?,
                a.contact_damping.unwrap_or(0.0),
                a.dt.context("--dt S is needed (or --scenario FILE)")?,
                "--mass".to_string(),
            ),
            (None, None) => bail!("give the apparent mass: --mass KG or --scenario FILE"),
        };
    let model = ForceLoop::new(mass, k, c, dt, a.delay)?;
    let sweep = match &a.k_sweep {
        None => default_sweep(k),
        Some(l) => match l.values.as_slice() {
            [lo, hi] if *lo > 0.0 && hi > lo => [*lo, *hi],
            _ => bail!(
                "--k-sweep '{}': two stiffnesses lo,hi in N/m, 0 < lo < hi",
                l.text
            ),
        },
    };
    let (gains, spec) = match &a.evaluate {
        Some(l) => match l.values.as_slice() {
            [kfp, kfi, kvd] => (
                ForceGains {
                    kfp: *kfp,
                    kfi: *kfi,
                    kvd: *kvd,
                },
                None,
            ),
            _ => bail!(
                "--evaluate '{}' has {} value(s); it takes three: kfp,kfi,kvd",
                l.text,
                l.values.len()
            ),
        },
        None => {
            let spec = DesignSpec::new(
                a.bandwidth_hz.unwrap_or(f64::NAN),
                a.damping.unwrap_or(f64::NAN),
                a.integral_hz,
            )?;
            (design(&model, &spec)?.0, Some(spec))
        }
    };
    let r = analyse(&model, &gains, sweep);
    if a.json {
        outln!(
            "{}",
            to_json(
                &report_json(&r, spec.as_ref(), sweep, &source, actuator.as_ref()),
                false
            )
        );
    } else {
        print_report(&r, spec.as_ref(), sweep, &source);
        if let Some(b) = &actuator {
            print_actuator(b, &r);
        }
    }
    Ok(())
}

/// What the actuators allow for a scenario's force step (`--scenario`): the push at its
/// contact pose and the bang-bang bound on settling, from rest at the touch.
struct ActuatorBound {
    limit: PushLimit,
    target_n: f64,
    stiffness: f64,
    settling_s: Option<f64>,
}

fn print_actuator(b: &ActuatorBound, r: &Analysis) {
    let l = &b.limit;
    outln!(
        "actuator limit (pushing into the surface): {:.0} N from the effort limits, gravity {:+.1} N along the push, apparent mass {:.4} kg",
        l.max_force_n,
        l.gravity_n,
        l.mass_kg
    );
    let travel = b.target_n / b.stiffness;
    match b.settling_s {
        Some(t) => {
            outln!(
                "  the {:.0} N step needs {:.4} m of travel: pushed bang-bang from rest it reaches the 5 % band (overshoot <= 2 %) {:.3} s after the touch at the earliest",
                b.target_n,
                travel,
                t
            );
            if r.stable && r.step.settling_s.is_some_and(|s| s < t) {
                outln!(
                    "  the model's {:.3} s is out of reach: the actuators, not the gains, set the pace (keep [force] anti_windup = true)",
                    r.step.settling_s.unwrap_or(t)
                );
            }
        }
        None => outln!(
            "  the {:.0} N step needs {:.4} m of travel: no bang-bang push settles it within 1 s",
            b.target_n,
            travel
        ),
    }
}

fn report_json(
    r: &Analysis,
    spec: Option<&DesignSpec>,
    sweep: [f64; 2],
    source: &str,
    actuator: Option<&ActuatorBound>,
) -> serde_json::Value {
    let m = &r.model;
    let range = r.range;
    json!({
        "kfp": r.gains.kfp,
        "kfi": r.gains.kfi,
        "kvd": r.gains.kvd,
        "stable": r.stable,
        "poles": r.poles.z().iter().map(|z| [z.re, z.im]).collect::<Vec<_>>(),
        "poles_s": r.poles.s().map(|s| [s.re, s.im]).collect::<Vec<_>>(),
        "spectral_radius": r.poles.spectral_radius(),
        "k_min": range.map(|x| x.k_min),
        "k_max": range.map(|x| x.k_max),
        "k_min_is_sweep_end": range.map(|x| x.k_min_is_sweep_end),
        "k_max_is_sweep_end": range.map(|x| x.k_max_is_sweep_end),
        "k_sweep": sweep,
        "min_damping_ratio": MIN_DAMPING_RATIO,
        "gain_margin": r.margins.gain_up,
        "gain_margin_db": r.margins.gain_up.map(|g| 20.0 * g.log10()),
        "gain_margin_down": r.margins.gain_down,
        "phase_margin_deg": r.margins.phase_deg,
        "crossover_hz": r.margins.crossover_hz,
        "model_step_overshoot_pct": r.step.overshoot_pct,
        "model_step_settling_s": r.step.settling_s,
        "mass_kg": m.mass_kg(),
        "stiffness": m.stiffness(),
        "contact_damping": m.damping(),
        "dt": m.dt(),
        "delay": m.delay(),
        "bandwidth_hz": spec.map(DesignSpec::bandwidth_hz),
        "damping": spec.map(DesignSpec::damping),
        "integral_hz": spec.map(DesignSpec::integral_hz),
        "mass_from": source,
        "actuator_max_force_n": actuator.map(|b| b.limit.max_force_n),
        "actuator_gravity_n": actuator.map(|b| b.limit.gravity_n),
        "step_n": actuator.map(|b| b.target_n),
        "bang_bang_settling_s": actuator.and_then(|b| b.settling_s),
    })
}

fn print_report(r: &Analysis, spec: Option<&DesignSpec>, sweep: [f64; 2], source: &str) {
    let m = &r.model;
    outln!(
        "force loop: apparent mass {:.4} kg ({source}), contact {} N/m and {} N s/m, period {} s{}",
        m.mass_kg(),
        m.stiffness(),
        m.damping(),
        m.dt(),
        if m.delay() {
            ", one period of delay"
        } else {
            ""
        }
    );
    if let Some(s) = spec {
        outln!(
            "design: dominant pair {} Hz, damping {}; integral pole {:.4} Hz",
            s.bandwidth_hz(),
            s.damping(),
            s.integral_hz()
        );
    }
    let g = &r.gains;
    outln!(
        "gains: kfp = {:.6}, kfi = {:.6} 1/s, kvd = {:.3} N s/m",
        g.kfp,
        g.kfi,
        g.kvd
    );
    outln!(
        "{} (spectral radius {:.6})",
        if r.stable { "stable" } else { "UNSTABLE" },
        r.poles.spectral_radius()
    );
    for (z, s) in r.poles.z().iter().zip(r.poles.s()) {
        outln!(
            "  pole z = {:+.6} {:+.6}j   s = {:+.3} {:+.3}j 1/s ({:.2} Hz)",
            z.re,
            z.im,
            s.re,
            s.im,
            s.norm() / (2.0 * std::f64::consts::PI)
        );
    }
    let opt = |v: Option<f64>, f: &dyn Fn(f64) -> String| v.map_or("-".to_string(), f);
    outln!(
        "gain margin: x{} ({} dB) up, x{} down; phase margin: {} deg at {} Hz",
        opt(r.margins.gain_up, &|v| format!("{v:.3}")),
        opt(r.margins.gain_up, &|v| format!("{:.1}", 20.0 * v.log10())),
        opt(r.margins.gain_down, &|v| format!("{v:.4}")),
        opt(r.margins.phase_deg, &|v| format!("{v:.1}")),
        opt(r.margins.crossover_hz, &|v| format!("{v:.2}")),
    );
    match r.range {
        None => outln!(
            "stiffness range: none (not stable with every oscillatory mode damped by at least {} at k = {} N/m)",
            MIN_DAMPING_RATIO,
            m.stiffness()
        ),
        Some(x) => outln!(
            "stiffness range (stable, every oscillatory mode damped by at least {}): [{:.0}, {:.0}] N/m{}{} (sweep [{}, {}])",
            MIN_DAMPING_RATIO,
            x.k_min,
            x.k_max,
            if x.k_min_is_sweep_end { "; k_min is the sweep's end" } else { "" },
            if x.k_max_is_sweep_end { "; k_max is the sweep's end" } else { "" },
            sweep[0],
            sweep[1]
        ),
    }
    if r.stable {
        outln!(
            "model step response: overshoot {:.2} %, settling (5 %) {}",
            r.step.overshoot_pct,
            r.step
                .settling_s
                .map_or("not within 10 s".into(), |t| format!("{t:.3} s"))
        );
    } else {
        outln!("model step response: grows without bound (unstable)");
    }
}
