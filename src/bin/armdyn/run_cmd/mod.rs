//! `armdyn run ...`: scenario files, and the thesis's trials as the built-in scenarios with
//! command-line overrides. Each run writes `trajectory.csv`, `metrics.json` and SVG figures
//! into its output folder (all or nothing) and prints where they are.

use std::path::{Path, PathBuf};

use anyhow::Context;
use clap::{Args, Subcommand};

use armdyn::robots::scara::presets::ForceReference;
use armdyn::scenario::{
    built_in, controller_model_for, write_outputs_for, ControllerModel, ForceController, LawChoice,
    Outcome, PositionController, ReferenceSpec, Scenario,
};
use armdyn::trajectory::SampledTrajectory;

use crate::precision::Precision;
use crate::progress::{Progress, StepLimit};

mod scenario_files;
pub(crate) mod summary;
mod thesis_trials;

use scenario_files::scenarios;
use summary::print_single;
pub use thesis_trials::hybrid;
use thesis_trials::position;

/// Arguments of `armdyn run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    #[command(subcommand)]
    trial: Trial,
}

#[derive(Debug, Subcommand)]
enum Trial {
    /// Run scenario files (`scenarios/*.toml`); several files print one comparison table.
    Scenario(ScenarioArgs),
    /// Position test trajectory (eq. 4.16) in free space, thesis Figures 4.3-4.9.
    Position(PositionArgs),
    /// A position controller alone on the contact trajectory (Section 5.1, Figures 5.3-5.4).
    Contact(ContactArgs),
    /// The configuration-switch trial (Section 4.4, Figure 4.14).
    ThreeZone(ThreeZoneArgs),
    /// Hybrid force/position control on the reaction surface (Chapter 5, Figures 5.8-5.11).
    Hybrid(HybridArgs),
    /// A position controller on a reference from a CSV file (header `t,x,y,z,yaw`; s, m, rad).
    Reference(ReferenceArgs),
    /// Any generated robot tracking a joint trajectory from a CSV file (`t,q1..qN`).
    JointReference(crate::joint_trial::JointReferenceArgs),
}

#[derive(Debug, Args)]
struct ScenarioArgs {
    /// Scenario files.
    #[arg(required = true, value_name = "FILE")]
    files: Vec<PathBuf>,
    /// Only check the files (every key, the workspace, the reach of the surface); run nothing.
    #[arg(long)]
    check: bool,
    /// Output folder (default `out/<name>`; with several files, `DIR/<name>/` each).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    #[command(flatten)]
    limit: StepLimit,
    /// Force law overriding the files': pi-ff, pi-ff-vd, impedance or admittance; a PI law
    /// may add `:thesis` (20, 5, 2000) or `:design` (from `[force.design]`). A comma-separated
    /// list runs every file with each law (into `DIR/<name>/<law>/`) and prints one table.
    #[arg(long, value_name = "LAW[,LAW...]", value_delimiter = ',', value_parser = parse_law_choice)]
    force_law: Vec<LawChoice>,
    /// The controller's model, over the files' `controller_model`: `nominal` or an
    /// `identification.json`.
    #[arg(long, value_name = "nominal|FILE")]
    controller_model: Option<String>,
    /// The controller's arithmetic: the library's controllers (`reference`), or the
    /// deployable hybrid step (`armdyn::robots::scara::deploy`) in `f64` or `f32`, for the scenarios it can
    /// run (PID-FL position loop, PI force law, a plane, a time switch; others are refused,
    /// naming the key).
    #[arg(long, value_enum, default_value_t = Precision::Reference)]
    precision: Precision,
    /// Run without the safety supervisor, over the files' `[safety]`.
    #[arg(long)]
    no_safety: bool,
    /// Write no viewer (`view.html`; `armdyn view DIR` writes it later).
    #[arg(long)]
    no_view: bool,
}

/// Simulation settings shared by the thesis trials (they override the scenario's).
#[derive(Debug, Clone, Args)]
pub struct SimArgs {
    /// Output folder (created; files in it are replaced only when the run succeeds).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Controller sample period, s.
    #[arg(long, default_value_t = 1e-3, value_name = "S")]
    control_dt: f64,
    /// RK4 step of the plant, s (the control period must be a whole multiple of it).
    #[arg(long, default_value_t = 1e-3, value_name = "S")]
    plant_dt: f64,
    /// Initial joint positions, one per joint of the trial's robot (rad or m); default:
    /// home, all zero, as the thesis's Simulink integrators start.
    #[arg(long, value_parser = crate::cli_args::parse_number_list, allow_hyphen_values = true, value_name = "Q")]
    q0: Option<crate::cli_args::NumberList>,
    #[command(flatten)]
    limit: StepLimit,
    /// The controller's model: `nominal` (the description's) or an `identification.json` of
    /// the trial's robot, written by `armdyn identify`.
    #[arg(long, default_value = "nominal", value_name = "nominal|FILE")]
    controller_model: String,
    /// Run without the safety supervisor, as the thesis's trials ran: nothing is checked and
    /// nothing trips (a diverging law then runs into the actuators' limits).
    #[arg(long)]
    no_safety: bool,
    /// Write no viewer (`view.html`; `armdyn view DIR` writes it later).
    #[arg(long)]
    no_view: bool,
}

#[derive(Debug, Args)]
struct PositionArgs {
    /// Controller: pid, pid-fl, fsf-place, fsf-lqr, pid-fl-central, computed-torque.
    #[arg(long, value_parser = parse_position, required_unless_present = "all", conflicts_with = "all")]
    controller: Option<PositionController>,
    /// Run every controller (into DIR/<name>/) and print one comparison table.
    #[arg(long)]
    all: bool,
    #[command(flatten)]
    sim: SimArgs,
}

#[derive(Debug, Args)]
struct ContactArgs {
    /// Position controller (as for `run position`).
    #[arg(long, value_parser = parse_position, default_value = "pid-fl")]
    controller: PositionController,
    #[command(flatten)]
    sim: SimArgs,
}

#[derive(Debug, Args)]
struct ThreeZoneArgs {
    /// Position controller (as for `run position`; default: computed-torque for the planned
    /// flip, pid-fl for the thesis's step).
    #[arg(long, value_parser = parse_position)]
    controller: Option<PositionController>,
    /// The elbow switch: `planned` (a quintic flip within 80 % of the effort limits, end
    /// stops on, start on the reference), `optimal` (the same with each move of the flip the
    /// shortest optimised one, `armdyn plan`'s) or `step` (the thesis's jump, its start at
    /// q = 0, no end stops).
    #[arg(long, value_parser = ["planned", "optimal", "step"], default_value = "planned")]
    elbow_switch: String,
    #[command(flatten)]
    sim: SimArgs,
}

#[derive(Debug, Args)]
pub struct HybridArgs {
    /// Force law: pi-ff (eq. 5.10) or pi-ff-vd (eq. 5.11).
    #[arg(long, value_parser = parse_force_controller, default_value = "pi-ff-vd")]
    force_controller: ForceController,
    /// Desired force: const (-200 N) or var (-200 - 200 sin(10 t / T) N), from 2 s.
    #[arg(long, value_parser = parse_force_reference, default_value = "const")]
    force: ForceReference,
    /// Run all four combinations (into DIR/<law>-<force>/) and print one comparison table.
    #[arg(long)]
    all: bool,
    /// Force sensor: standard deviation of white noise on each force axis, N (default: ideal).
    #[arg(long, default_value_t = 0.0, value_name = "N")]
    sensor_noise: f64,
    /// Force sensor: bias on fz, N.
    #[arg(
        long,
        default_value_t = 0.0,
        value_name = "N",
        allow_hyphen_values = true
    )]
    sensor_bias: f64,
    /// Force sensor: first-order low-pass cutoff, Hz (default: no filter).
    #[arg(long, value_name = "HZ")]
    sensor_cutoff: Option<f64>,
    /// Force sensor: seed of the noise generator.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    #[command(flatten)]
    sim: SimArgs,
}

impl HybridArgs {
    /// The main job: PI + feedforward + velocity damping, constant force, `out/hybrid`.
    pub fn default_trial() -> Self {
        Self {
            force_controller: ForceController::PiFfVd,
            force: ForceReference::Const,
            all: false,
            sensor_noise: 0.0,
            sensor_bias: 0.0,
            sensor_cutoff: None,
            seed: 1,
            sim: SimArgs {
                out: None,
                control_dt: 1e-3,
                plant_dt: 1e-3,
                q0: None,
                limit: StepLimit::default(),
                controller_model: "nominal".into(),
                no_safety: false,
                no_view: false,
            },
        }
    }
}

#[derive(Debug, Args)]
struct ReferenceArgs {
    /// The reference: CSV with header `t,x,y,z,yaw` (s, m, m, m, rad), strictly increasing t.
    #[arg(long, value_name = "FILE")]
    csv: PathBuf,
    /// Position controller (as for `run position`).
    #[arg(long, value_parser = parse_position, default_value = "pid-fl")]
    controller: PositionController,
    #[command(flatten)]
    sim: SimArgs,
}

fn parse_position(s: &str) -> Result<PositionController, String> {
    PositionController::parse(s).map_err(|e| e.to_string())
}

fn parse_force_controller(s: &str) -> Result<ForceController, String> {
    ForceController::parse(s).map_err(|e| e.to_string())
}

fn parse_law_choice(s: &str) -> Result<LawChoice, String> {
    LawChoice::parse(s)
}

fn parse_force_reference(s: &str) -> Result<ForceReference, String> {
    ForceReference::parse(s).map_err(|e| e.to_string())
}

/// Runs `armdyn run ...`.
pub fn run_cmd(args: &RunArgs) -> anyhow::Result<()> {
    match &args.trial {
        Trial::Scenario(a) => scenarios(a),
        Trial::Position(a) => position(a),
        Trial::Hybrid(a) => hybrid(a),
        Trial::Contact(a) => {
            let mut s = built_in("thesis-contact.toml")?;
            s.position = a.controller;
            single(s, "contact", &a.sim)
        }
        Trial::ThreeZone(a) => {
            let planned = a.elbow_switch != "step";
            let mut s = built_in(if planned {
                "three-zone.toml"
            } else {
                "thesis-three-zone.toml"
            })?;
            if a.elbow_switch == "optimal" {
                s.reference_robot_keys
                    .insert("elbow_switch".into(), "optimal".into());
                s.name = "three-zone-optimal".into();
            }
            if let Some(c) = a.controller {
                s.position = c;
            }
            if planned && a.sim.q0.is_some() {
                s.start_on_reference = false;
            }
            single(s, "three-zone", &a.sim)
        }
        Trial::Reference(a) => {
            let file = std::fs::File::open(&a.csv)
                .with_context(|| format!("cannot open reference {}", a.csv.display()))?;
            let reference = SampledTrajectory::from_csv_reader(std::io::BufReader::new(file))
                .with_context(|| format!("reference {}", a.csv.display()))?;
            let mut s = built_in("thesis-three-zone.toml")?;
            s.name = "reference".into();
            s.reference = ReferenceSpec::Csv(a.csv.clone(), reference);
            s.position = a.controller;
            single(s, "reference", &a.sim)
        }
        Trial::JointReference(a) => crate::joint_trial::run(a),
    }
}

/// The thesis trial's settings from the command line, over the built-in scenario's.
fn apply_sim(s: &mut Scenario, sim: &SimArgs) -> anyhow::Result<()> {
    s.control_dt_s = sim.control_dt;
    s.plant_dt_s = sim.plant_dt;
    s.q0 = Some(crate::cli_args::joint_list(
        "--q0",
        &s.robot,
        s.dof,
        sim.q0.as_ref(),
    )?);
    s.controller_model = controller_model(s, &sim.controller_model)?;
    if sim.no_safety {
        s.safety.enabled = false;
    }
    Ok(())
}

/// `--controller-model`: `nominal` or an `identification.json` of `scenario`'s robot.
pub fn controller_model(scenario: &Scenario, arg: &str) -> anyhow::Result<ControllerModel> {
    controller_model_for(scenario, arg)
        .map_err(|e| anyhow::anyhow!(e))
        .context("--controller-model")
}

/// Checks, runs and writes one scenario of any robot of the registry; `what` names it in
/// messages.
pub(crate) fn run_one(
    s: &Scenario,
    what: &str,
    out: &Path,
    limit: &StepLimit,
    precision: Precision,
    view: bool,
) -> anyhow::Result<Outcome> {
    limit.check_scenario(what, s)?;
    // The body is the robot's own code: `?` returns from this function.
    armdyn::with_robot_named!(s.robot.as_str(), |robot: R, N, _module| {
        let prepared = precision
            .prepare_for(s, robot)
            .with_context(|| format!("{what}: nothing was simulated"))?;
        // Again, exactly: planning may have added pauses (a planned elbow flip).
        limit.check_config(what, &prepared.config)?;
        let mut progress = Progress::start(what, 0.0, prepared.config.duration);
        let recorded = prepared
            .execute(s, |t| progress.update(t))
            .with_context(|| format!("{what}: simulation stopped; no files were written"))?;
        progress.finish();
        write_outputs_for(out, s, &recorded, view, &robot)?;
        Ok(recorded.outcome)
    })
    .unwrap_or_else(|| Err(anyhow::anyhow!("{what}: unknown robot `{}`", s.robot)))
}

/// [`run_one`] of a thesis trial with the command line's settings `sim`.
fn run_sim(s: &Scenario, what: &str, out: &Path, sim: &SimArgs) -> anyhow::Result<Outcome> {
    run_one(s, what, out, &sim.limit, Precision::Reference, !sim.no_view)
}

fn single(mut s: Scenario, trial: &str, sim: &SimArgs) -> anyhow::Result<()> {
    apply_sim(&mut s, sim)?;
    let out = sim
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("out/{trial}")));
    let what = format!("{trial} {}", s.position.name());
    let r = run_one(
        &s,
        &what,
        &out,
        &sim.limit,
        Precision::Reference,
        !sim.no_view,
    )?;
    print_single(&what, &r, &out);
    Ok(())
}
