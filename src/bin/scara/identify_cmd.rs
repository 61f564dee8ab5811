//! `scara identify`: dynamic identification of a robot on its simulated plant; writes
//! `identification.json` and the measured-against-predicted torque figures.

use std::path::PathBuf;

use anyhow::Context;
use clap::{Args, ValueEnum};

use scara::identification::file::to_json;
use scara::identification::{identify, Identifiable, Identification, IdentifySettings};
use scara::model::{Planar2, Puma560, RobotModel, Scara, ScaraMdh};
use scara::report::data_plots::{time_panels, Panel};
use scara::report::{OutputDir, Table};

/// On or off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OnOff {
    /// On.
    On,
    /// Off.
    Off,
}

/// Arguments of `scara identify`.
#[derive(Debug, Args)]
pub struct IdentifyArgs {
    /// Robot to identify: scara, scara_mdh, puma560 or planar2 (the robots with an
    /// identification model).
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
    /// Output folder (default `out/identify-<robot>`).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
}

/// Runs `scara identify`.
pub fn run(a: &IdentifyArgs) -> anyhow::Result<()> {
    if !(a.noise_pct.is_finite() && (0.0..=100.0).contains(&a.noise_pct)) {
        anyhow::bail!(
            "--noise-pct {}: must be a percentage in [0, 100]",
            a.noise_pct
        );
    }
    let mut settings = IdentifySettings::new(a.noise_pct, a.friction == OnOff::On, a.seed);
    settings.excitation.evaluations = a.evaluations;
    match a.robot.as_str() {
        "scara" => report(&Scara, &settings, a),
        "scara_mdh" | "scara-mdh" => report(&ScaraMdh, &settings, a),
        "puma560" => report(&Puma560, &settings, a),
        "planar2" => report(&Planar2, &settings, a),
        other => anyhow::bail!(
            "--robot {other}: identification is available for scara, scara_mdh, puma560 and planar2"
        ),
    }
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
    out.write("validation_torques.svg", torque_figure(&id)?)?;
    out.commit()
        .with_context(|| format!("cannot write into {}", dir.display()))?;
    print(&id);
    outln!(
        "wrote {}/: identification.json, validation_torques.svg",
        dir.display()
    );
    Ok(())
}

fn torque_figure<const N: usize>(id: &Identification<N>) -> anyhow::Result<String> {
    let v = &id.validation;
    let panels: Vec<Panel> = (0..N)
        .map(|i| {
            let unit = if v.q.is_empty() {
                "N m"
            } else {
                match scara_unit(id.robot, i) {
                    true => "N",
                    false => "N m",
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

/// Whether joint `i` of the named robot is prismatic (its torque is a force, N).
fn scara_unit(robot: &str, i: usize) -> bool {
    use scara::model::JointKind;
    let kinds: &[JointKind] = match robot {
        "scara" => &<Scara as RobotModel<4>>::JOINT_KINDS,
        "scara_mdh" => &<ScaraMdh as RobotModel<4>>::JOINT_KINDS,
        "puma560" => &<Puma560 as RobotModel<6>>::JOINT_KINDS,
        _ => &<Planar2 as RobotModel<2>>::JOINT_KINDS,
    };
    kinds.get(i) == Some(&JointKind::Prismatic)
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
