//! `armdyn identify`: dynamic identification of a robot on its simulated plant; writes
//! `identification.json` and the measured-against-predicted torque figures. From a recorded
//! log, and the excitation and example-log companions: [`super::identify_log_cmd`].

use std::path::PathBuf;

use anyhow::Context;
use clap::Args;

use super::cli_args::OnOff;

use armdyn::identification::file::to_json;
use armdyn::identification::{identify, Identifiable, Identification, IdentifySettings};
use armdyn::model::RobotModel;
use armdyn::report::data_plots::{time_panels, Panel};
use armdyn::report::{OutputDir, Table};

/// Arguments of `armdyn identify`.
#[derive(Debug, Args)]
pub struct IdentifyArgs {
    /// Robot to identify: any generated robot (`scara`, `puma560`, `ur5`, `panda`, ...).
    #[arg(long)]
    robot: String,
    /// Torque noise, % of each joint's RMS torque (1 sigma).
    #[arg(
        long,
        default_value_t = 1.0,
        value_name = "P",
        allow_hyphen_values = true
    )]
    noise_pct: f64,
    /// Viscous + Coulomb joint friction in the plant, identified too.
    #[arg(long, value_enum, default_value_t = OnOff::Off)]
    friction: OnOff,
    /// Seed of everything random.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Cost evaluations of the excitation search.
    #[arg(long, default_value_t = 1500, value_name = "N")]
    evaluations: usize,
    /// Output folder (default `out/identify-<robot>`, `out/identify-<robot>-log` with --log,
    /// `out/excitation-<robot>` with --excitation-only).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Identification from a recorded log, and its companions.
    #[command(flatten)]
    log: super::identify_log_cmd::LogArgs,
}

/// Runs `armdyn identify`.
pub fn run(a: &IdentifyArgs) -> anyhow::Result<()> {
    if !(a.noise_pct.is_finite() && (0.0..=100.0).contains(&a.noise_pct)) {
        anyhow::bail!(
            "--noise-pct {}: must be a percentage in [0, 100]",
            a.noise_pct
        );
    }
    let mut settings = IdentifySettings::new(a.noise_pct, a.friction == OnOff::On, a.seed);
    settings.excitation.evaluations = a.evaluations;
    let common = super::identify_companions::Common {
        settings: &settings,
        out: a.out.as_deref(),
    };
    let name = a.robot.replace('-', "_");
    armdyn::with_robot_named!(name.as_str(), |robot: R, N, module| {
        if a.log.active() {
            super::identify_log_cmd::run(&robot, module::URDF, &a.log, &common)
        } else {
            report(&robot, &settings, a)
        }
    })
    .unwrap_or_else(|| {
        anyhow::bail!(
            "--robot {}: no such robot (one of {})",
            a.robot,
            armdyn::model::ROBOTS.join(", ")
        )
    })
}

fn report<const N: usize, R: Identifiable<N>>(
    robot: &R,
    settings: &IdentifySettings,
    a: &IdentifyArgs,
) -> anyhow::Result<()> {
    let id = identify(robot, settings)
        .with_context(|| format!("identifying {}: nothing was written", R::NAME))?;
    let dir = a
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("out/identify-{}", R::NAME)));
    let mut out =
        OutputDir::create(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    out.write(
        "identification.json",
        serde_json::to_string_pretty(&to_json(&id))? + "\n",
    )?;
    out.write("validation_torques.svg", torque_figure::<N, R>(&id)?)?;
    out.commit()
        .with_context(|| format!("cannot write into {}", dir.display()))?;
    print(&id);
    outln!(
        "wrote {}/: identification.json, validation_torques.svg",
        dir.display()
    );
    Ok(())
}

fn torque_figure<const N: usize, R: RobotModel<N>>(
    id: &Identification<N>,
) -> anyhow::Result<String> {
    let v = &id.validation;
    let panels: Vec<Panel> = (0..N)
        .map(|i| {
            let unit = if v.q.is_empty() {
                "N m"
            } else {
                match R::JOINT_KINDS.get(i) {
                    Some(armdyn::model::JointKind::Prismatic) => "N",
                    _ => "N m",
                }
            };
            Panel {
                title: format!(
                    "joint {}: RMS prediction error {:.2} % of the measured RMS torque",
                    i + 1,
                    id.validation_error_pct[i]
                ),
                y_label: format!("tau{} ({unit})", i + 1),
                series: vec![
                    (
                        "measured".into(),
                        v.t.iter().zip(&v.tau).map(|(t, x)| (*t, x[i])).collect(),
                    ),
                    (
                        "predicted by the estimate".into(),
                        v.t.iter()
                            .enumerate()
                            .map(|(k, t)| (*t, id.validation_predicted[k * N + i]))
                            .collect(),
                    ),
                ],
            }
        })
        .collect();
    Ok(time_panels(
        &format!(
            "{}: validation trajectory, measured and predicted torques",
            id.robot
        ),
        &panels,
    )?)
}

fn print<const N: usize>(id: &Identification<N>) {
    outln!(
        "{}: {} base parameters (of {}), noise {} %, friction {}, seed {}",
        id.robot,
        id.base.count(),
        id.base.parameter_names().len(),
        id.settings.noise_pct,
        if id.friction.is_some() { "on" } else { "off" },
        id.settings.seed
    );
    outln!(
        "excitation: condition number {:.1} (best random start {:.1}, {} evaluations)\n",
        id.excitation.condition_number,
        id.excitation.initial_condition_number,
        id.excitation.evaluations
    );
    let mut t = Table::new([
        "base parameter",
        "true",
        "estimated (WLS)",
        "relative error",
        "rel. std (%)",
    ]);
    for (k, name) in id.base.names().iter().enumerate() {
        t.push_row([
            name.clone(),
            format!("{:.6e}", id.truth[k]),
            format!("{:.6e}", id.estimate.weighted[k]),
            format!("{:.2e}", id.relative_errors[k]),
            format!("{:.3}", id.estimate.relative_std_pct[k]),
        ]);
    }
    outln!("{}", t.markdown());
    outln!("physical consistency: {}", id.consistency.summary());
    let join = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:.3}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    outln!(
        "validation torque RMS error (% of each joint's RMS torque): {} (against the noise-free torques: {})",
        join(&id.validation_error_pct),
        join(&id.validation_error_noise_free_pct)
    );
}
