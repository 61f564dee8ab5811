//! The companions of `armdyn identify --log`: `--excitation-only` writes the excitation to run
//! on the robot; `--write-log FILE` makes an example log on the simulated plant, optionally
//! with what a real robot has and the identification does not model (`--break-link`,
//! `--unmodelled-friction`), for `--log-seconds`.

use std::path::{Path, PathBuf};

use anyhow::Context;

use armdyn::identification::excitation::{self, design, ExcitationLimits};
use armdyn::identification::sim_log::{logged_csv, simulated_log, LogDefects, LogRecipe};
use armdyn::identification::unmodelled::{
    Unmodelled, ASYMMETRY, STRIBECK_FRACTION, STRIBECK_VELOCITY, TRIANGLE_EXCESS,
};
use armdyn::identification::{plant_friction, Identifiable, IdentifySettings};
use armdyn::model::ParametricModel;
use armdyn::report::{write_atomic, OutputDir};

use super::progress::num;

/// What the common `armdyn identify` options say, for the log modes.
pub struct Common<'a> {
    /// The simulated identification's settings (noise, friction, seed, search).
    pub settings: &'a IdentifySettings,
    /// `--out`.
    pub out: Option<&'a Path>,
}

/// What `--write-log` makes beyond the simulated plant's defaults.
pub struct LogOptions {
    /// `--log-seconds`.
    pub seconds: Option<f64>,
    /// `--lost-pct`.
    pub lost_pct: f64,
    /// `--break-link`, `--unmodelled-friction`.
    pub unmodelled: Unmodelled,
}

/// `--excitation-only`: the excitation at `rate` Hz into `--out`.
pub fn excitation_only<const N: usize, R: Identifiable<N>>(
    robot: &R,
    rate: f64,
    common: &Common<'_>,
) -> anyhow::Result<()> {
    if !(rate.is_finite() && rate > 0.0 && rate <= 1e5) {
        anyhow::bail!("--excitation-rate-hz {rate}: must be in (0, 100000]");
    }
    let s = common.settings;
    let smoothing = s.friction.then(|| plant_friction(robot).smoothing());
    let base = armdyn::identification::BaseParameters::of_robot(
        robot,
        smoothing,
        armdyn::identification::BASE_STATES,
        s.seed,
    )?;
    let limits = ExcitationLimits::default_for::<R>();
    let e = design(robot, &base, smoothing, &limits, &s.excitation);
    if let Some(v) = excitation::check_limits::<N, R>(&e.trajectory, &limits) {
        anyhow::bail!("the designed excitation breaks a limit: {v}");
    }
    let period = e.trajectory.period_s();
    let samples = libm::round(period * rate) as usize;
    let mut csv = String::from("t");
    for p in ["q", "qd", "qdd"] {
        for i in 1..=N {
            csv.push_str(&format!(",{p}{i}"));
        }
    }
    csv.push('\n');
    for k in 0..=samples {
        let t = k as f64 / rate;
        let (q, qd, qdd) = e.trajectory.state(t);
        csv.push_str(&format!("{t}"));
        for x in q.iter().chain(qd.iter()).chain(qdd.iter()) {
            csv.push_str(&format!(",{x}"));
        }
        csv.push('\n');
    }
    let dir = common.out.map_or_else(
        || PathBuf::from(format!("out/excitation-{}", R::NAME)),
        Path::to_path_buf,
    );
    let mut out =
        OutputDir::create(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    out.write("excitation.csv", csv)?;
    out.commit()
        .with_context(|| format!("cannot write into {}", dir.display()))?;
    let peak = e
        .peak_effort_fraction
        .iter()
        .map(|p| format!("{:.0} %", 100.0 * p))
        .collect::<Vec<_>>()
        .join(", ");
    outln!(
        "{}: excitation of period {period} s (one period, periodic: repeat it as often as wanted), condition number {:.1}; within the joint limits (margin {:.0} %), {} rad/s, {} rad/s^2 (revolute) and {:.0} % of the efforts (peak effort per joint on the nominal model: {peak})",
        R::NAME,
        e.condition_number,
        100.0 * limits.position_margin,
        limits.velocity[0],
        limits.acceleration[0],
        100.0 * limits.effort_fraction
    );
    outln!(
        "wrote {}/excitation.csv: t, q1..q{N}, qd1..qd{N}, qdd1..qdd{N} at {rate} Hz ({} rows)",
        dir.display(),
        samples + 1
    );
    Ok(())
}

/// `--write-log FILE`: an example log made on the simulated plant.
pub fn write_log<const N: usize, R: Identifiable<N> + ParametricModel<N>>(
    robot: &R,
    path: &Path,
    a: &LogOptions,
    common: &Common<'_>,
) -> anyhow::Result<()> {
    let s = common.settings;
    if !(a.lost_pct.is_finite() && (0.0..100.0).contains(&a.lost_pct)) {
        anyhow::bail!(
            "--lost-pct {}: must be a percentage in [0, 100)",
            a.lost_pct
        );
    }
    if let Some(d) = a.seconds {
        if !(d.is_finite() && d > 0.0 && d <= 3600.0) {
            anyhow::bail!("--log-seconds {d}: must be in (0, 3600]");
        }
    }
    if let Some(l) = a.unmodelled.broken_link {
        if !(1..=N).contains(&l) {
            anyhow::bail!("--break-link {l}: {} has links 1 to {N}", R::NAME);
        }
    }
    let unmodelled = a.unmodelled;
    if unmodelled.friction && !s.friction {
        anyhow::bail!(
            "--unmodelled-friction: needs --friction on (it adds to the plant's friction)"
        );
    }
    let recipe = LogRecipe {
        seconds: a.seconds,
        defects: LogDefects {
            drop_probability: a.lost_pct / 100.0,
            ..LogDefects::default()
        },
        unmodelled,
    };
    let made = simulated_log(robot, s, &recipe)
        .with_context(|| format!("--write-log {}: nothing was written", path.display()))?;
    let (log, defects) = (&made.log, recipe.defects);
    let text = logged_csv(log);
    write_atomic(path, text.as_bytes())
        .with_context(|| format!("cannot write {}", path.display()))?;
    let mut plant = String::new();
    if let Some(l) = unmodelled.broken_link {
        plant.push_str(&format!(
            ", link {l}'s inertia breaking the triangle inequality (largest principal moment {} x the sum of the others)",
            1.0 + TRIANGLE_EXCESS
        ));
    }
    if unmodelled.friction {
        plant.push_str(&format!(
            ", unmodelled friction (Stribeck {STRIBECK_FRACTION} x Coulomb over {STRIBECK_VELOCITY} rad/s, Coulomb asymmetry {ASYMMETRY})"
        ));
    }
    outln!(
        "{}: wrote {} ({} rows) from the simulated plant: {} s of the {} s excitation, noise {} %, friction {}{plant}, defects {defects:?}",
        R::NAME,
        path.display(),
        log.len(),
        num(made.duration_s),
        made.period_s,
        s.noise_pct,
        if s.friction { "on" } else { "off" },
    );
    Ok(())
}
