//! `armdyn run joint-reference`: any generated robot tracks a joint trajectory from a CSV file
//! (`t,q1..qn`) in free space, with computed torque or PID with feedback linearization: a
//! scenario of `kind = "joints"` built from the arguments and run by the library; writes
//! `trajectory.csv`, `metrics.json` and SVG figures like the other runs.

use std::path::PathBuf;

use anyhow::Context;
use clap::{Args, ValueEnum};

use armdyn::scenario::Scenario;

use crate::cli_args::robot_parser;
use crate::precision::Precision;
use crate::progress::StepLimit;

/// The joint-space controllers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum JointController {
    /// `tau = M (qdd_d + Kp e + Kd e') + c + g`, critically damped at `--omega`.
    ComputedTorque,
    /// The thesis's PID with feedback linearization (poles -8, -9, -10 on the diagonal of the
    /// constant part of M), with the reference's acceleration fed forward.
    PidFl,
}

/// Arguments of `armdyn run joint-reference`.
#[derive(Debug, Args)]
pub struct JointReferenceArgs {
    /// Robot (any generated robot).
    #[arg(long, value_parser = robot_parser())]
    robot: String,
    /// Joint reference, CSV with header `t,q1,...,qN` (s; rad or m), from t = 0, interpolated
    /// by a natural cubic spline.
    #[arg(long, value_name = "FILE")]
    csv: PathBuf,
    /// Controller.
    #[arg(long, value_enum)]
    controller: JointController,
    /// Natural frequency of computed torque's error dynamics, rad/s.
    #[arg(long, default_value_t = 20.0, value_name = "RAD_S")]
    omega: f64,
    /// Start of the metrics' "after" window (max and RMS error after it), s.
    #[arg(long, default_value_t = 1.0, value_name = "S")]
    after: f64,
    /// Controller sample period and RK4 step, s.
    #[arg(long, default_value_t = 1e-3, value_name = "S")]
    dt: f64,
    /// Output folder (default `out/joint-reference-<robot>`).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Write no viewer (`view.html`; `armdyn view DIR` writes it later).
    #[arg(long)]
    pub no_view: bool,
}

/// The scenario the arguments describe.
fn scenario(args: &JointReferenceArgs) -> anyhow::Result<Scenario> {
    let robot = &args.robot;
    let csv = std::path::absolute(&args.csv)
        .with_context(|| format!("cannot resolve {}", args.csv.display()))?;
    let file = toml::Value::String(csv.display().to_string());
    let (law, extra) = match args.controller {
        JointController::ComputedTorque => {
            anyhow::ensure!(
                args.omega.is_finite() && args.omega > 0.0,
                "--omega must be a positive number of rad/s"
            );
            ("computed-torque", format!("omega_rad_s = [{}]", args.omega))
        }
        JointController::PidFl => ("pid-fl", "acceleration_feedforward = true".to_string()),
    };
    let text = format!(
        "format = 1\nname = \"joint-reference-{robot}\"\nrobot = \"{robot}\"\nstart_on_reference = true\nend_stops = false\ncontrol_dt_s = {dt}\nplant_dt_s = {dt}\n\n[reference]\nkind = \"joints\"\nfile = {file}\n\n[position]\nlaw = \"{law}\"\n{extra}\n\n[metrics]\nafter_s = {after}\n",
        dt = args.dt,
        after = args.after,
    );
    Ok(Scenario::parse(
        &format!("joint-reference --robot {robot}"),
        &text,
        std::path::Path::new("."),
    )?)
}

/// Runs `armdyn run joint-reference`.
pub fn run(args: &JointReferenceArgs) -> anyhow::Result<()> {
    let s = scenario(args)?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("out/joint-reference-{}", s.robot)));
    let r = crate::run_cmd::run_one(
        &s,
        &s.robot,
        &out,
        &StepLimit::default(),
        Precision::Reference,
        !args.no_view,
    )?;
    let max_after = r
        .tracking_after
        .max_joint_error_after
        .iter()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    outln!(
        "{} with {}: max |joint error| after {} s = {:.3e} (rad or m); wrote {}",
        s.robot,
        r.controller_name,
        args.after,
        max_after,
        out.display()
    );
    Ok(())
}
