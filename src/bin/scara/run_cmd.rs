//! `scara run ...`: the thesis's trials. Each writes `trajectory.csv`, `metrics.json` and
//! SVG figures into its output folder (all or nothing) and prints where they are.

use std::path::{Path, PathBuf};

use anyhow::Context;
use clap::{Args, Subcommand};
use serde_json::{json, Value};

use scara::contact::{Environment, ForceSensor, FreeSpace, ReactionSurface, Sensed};
use scara::control::Controller;
use scara::kinematics::{ElbowPlan, ScaraGeometry, SwitchPolicy};
use scara::metrics::{ForceMetrics, ForceSummary, TrackingMetrics, TrackingSummary};
use scara::model::{RobotModel, Scara, Wrench};
use scara::report::{self, OutputDir, SurfacePatch, Table};
use scara::scenario::{
    run, ForceController, ForceReference, GainReport, HybridSetup, PositionController, RunOutput,
    ScaraReference,
};
use scara::sim::SimConfig;
use scara::trajectory::{
    CartesianTrajectory, ContactTest, ForceProfile, PositionTest, SampledTrajectory, ThreeZone,
};

/// Arguments of `scara run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    #[command(subcommand)]
    trial: Trial,
}

#[derive(Debug, Subcommand)]
enum Trial {
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
}

/// Simulation settings shared by every trial.
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
    /// Initial joint positions q1,q2,d3,q4 (rad, rad, m, rad); default: home, all zero, as
    /// the thesis's Simulink integrators start.
    #[arg(long, value_parser = crate::cli_args::parse_number_list, allow_hyphen_values = true, value_name = "Q")]
    q0: Option<crate::cli_args::NumberList>,
    #[command(flatten)]
    limit: crate::progress::StepLimit,
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
    /// Position controller (as for `run position`).
    #[arg(long, value_parser = parse_position, default_value = "pid-fl")]
    controller: PositionController,
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
                limit: crate::progress::StepLimit::default(),
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

fn parse_force_reference(s: &str) -> Result<ForceReference, String> {
    ForceReference::parse(s).map_err(|e| e.to_string())
}

/// Runs `scara run ...`.
pub fn run_cmd(args: &RunArgs) -> anyhow::Result<()> {
    match &args.trial {
        Trial::Position(a) => position(a),
        Trial::Hybrid(a) => hybrid(a),
        Trial::Contact(a) => {
            let trajectory = ContactTest::thesis();
            single(
                a.controller,
                "contact",
                &trajectory,
                Surface::Thesis,
                &a.sim,
            )
        }
        Trial::ThreeZone(a) => {
            let trajectory = ThreeZone::new();
            single(
                a.controller,
                "three-zone",
                &trajectory,
                Surface::None,
                &a.sim,
            )
        }
        Trial::Reference(a) => {
            let file = std::fs::File::open(&a.csv)
                .with_context(|| format!("cannot open reference {}", a.csv.display()))?;
            let reference = SampledTrajectory::from_csv_reader(std::io::BufReader::new(file))
                .with_context(|| format!("reference {}", a.csv.display()))?;
            single(a.controller, "reference", &reference, Surface::None, &a.sim)
        }
    }
}

/// One position controller on one reference, into `--out` (default `out/<trial>`).
fn single(
    controller: PositionController,
    trial: &'static str,
    trajectory: &dyn CartesianTrajectory,
    surface: Surface,
    sim: &SimArgs,
) -> anyhow::Result<()> {
    let out = sim.out_or(&format!("out/{trial}"));
    let mut spec = Spec::position(controller, trial, trajectory, None, surface)?;
    let result = execute(&mut spec, sim)?;
    write(&out, &spec, &result)?;
    print_single(&spec, &result, &out);
    Ok(())
}

impl SimArgs {
    fn out_or(&self, default: &str) -> PathBuf {
        self.out.clone().unwrap_or_else(|| PathBuf::from(default))
    }
}

fn position(a: &PositionArgs) -> anyhow::Result<()> {
    let root = a.sim.out_or("out/position");
    let list: Vec<PositionController> = match a.controller {
        Some(c) if !a.all => vec![c],
        _ => PositionController::ALL.to_vec(),
    };
    let mut table = Table::new([
        "controller",
        "max |e| after 2 s (q1, q2, d3, q4)",
        "RMS |e| after 2 s",
        "max |tau| (N m, N)",
    ]);
    for c in &list {
        let trajectory = PositionTest::new();
        let mut spec = Spec::position(*c, "position", &trajectory, None, Surface::None)?;
        let result = execute(&mut spec, &a.sim)?;
        let out = if a.all {
            root.join(c.name())
        } else {
            root.clone()
        };
        write(&out, &spec, &result)?;
        if !a.all {
            print_single(&spec, &result, &out);
            return Ok(());
        }
        let t = &result.tracking;
        table.push_row([
            c.name().to_string(),
            join(t.max_joint_error_after.as_slice(), |x| format!("{x:.2e}")),
            join(t.rms_joint_error_after.as_slice(), |x| format!("{x:.2e}")),
            join(t.max_abs_tau.as_slice(), |x| format!("{x:.1}")),
        ]);
        eprintln!("wrote {}", out.display());
    }
    let md = table.markdown();
    println!("Position test (eq. 4.16), errors in rad or m:\n\n{md}");
    report::write_atomic(root.join("comparison.md"), &md)?;
    println!("comparison table: {}", root.join("comparison.md").display());
    Ok(())
}

/// `scara run hybrid` (and the default command).
pub fn hybrid(a: &HybridArgs) -> anyhow::Result<()> {
    let root = a.sim.out_or("out/hybrid");
    let combos: Vec<(ForceController, ForceReference)> = if a.all {
        ForceController::ALL
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
    ]);
    let noise = Wrench::new(
        a.sensor_noise,
        a.sensor_noise,
        a.sensor_noise,
        0.0,
        0.0,
        0.0,
    );
    let bias = Wrench::new(0.0, 0.0, a.sensor_bias, 0.0, 0.0, 0.0);
    let sensor =
        ForceSensor::new(bias, noise, a.sensor_cutoff, a.seed).context("force sensor settings")?;
    let ideal = a.sensor_noise == 0.0 && a.sensor_bias == 0.0 && a.sensor_cutoff.is_none();
    for (f, r) in &combos {
        let (controller, mut gains) = HybridSetup::build(*f).map_err(anyhow::Error::msg)?;
        let controller: Box<dyn Controller<4>> = if ideal {
            controller
        } else {
            gains.note = format!(
                "{}; force sensor: noise {} N (1 sigma per axis), bias {} N on fz, low-pass {}, seed {}",
                gains.note,
                a.sensor_noise,
                a.sensor_bias,
                a.sensor_cutoff.map_or("none".to_string(), |c| format!("{c} Hz")),
                a.seed
            );
            Box::new(Sensed::new(controller, sensor.clone()))
        };
        let trajectory = ContactTest::thesis();
        let mut spec = Spec {
            name: format!("hybrid {} {}", f.name(), r.name()),
            trial: "hybrid",
            controller,
            gains,
            trajectory: &trajectory,
            force: Some(r.profile()),
            surface: Surface::Thesis,
        };
        let result = execute(&mut spec, &a.sim)?;
        let out = if a.all {
            root.join(format!("{}-{}", f.name(), r.name()))
        } else {
            root.clone()
        };
        write(&out, &spec, &result)?;
        let fm = result
            .force
            .as_ref()
            .context("hybrid runs have force metrics")?;
        table.push_row([
            f.name().to_string(),
            r.name().to_string(),
            format!("{:.1}", fm.force_overshoot_pct),
            fm.settling_time_s
                .map_or("not settled".into(), |s| format!("{s:.3}")),
            format!("{:.2}", fm.force_rms_error_last_n),
            format!("{:.2}", fm.xy_rms_error_contact_mm),
            format!("{:.4}", fm.min_z_m),
        ]);
        if !a.all {
            print_single(&spec, &result, &out);
            return Ok(());
        }
        eprintln!("wrote {}", out.display());
    }
    let md = table.markdown();
    println!(
        "Hybrid force/position trial (contact reference B.3, surface z = 0.13 m, 10 kN/m):\n\n{md}"
    );
    report::write_atomic(root.join("comparison.md"), &md)?;
    println!("comparison table: {}", root.join("comparison.md").display());
    Ok(())
}

fn join(v: &[f64], format: impl Fn(f64) -> String) -> String {
    v.iter().map(|x| format(*x)).collect::<Vec<_>>().join(", ")
}

#[derive(Clone, Copy)]
enum Surface {
    None,
    Thesis,
}

struct Spec<'a> {
    name: String,
    trial: &'static str,
    controller: Box<dyn Controller<4>>,
    gains: GainReport,
    trajectory: &'a dyn CartesianTrajectory,
    force: Option<ForceProfile>,
    surface: Surface,
}

impl<'a> Spec<'a> {
    fn position(
        c: PositionController,
        trial: &'static str,
        trajectory: &'a dyn CartesianTrajectory,
        force: Option<ForceProfile>,
        surface: Surface,
    ) -> anyhow::Result<Self> {
        let (controller, gains) = c.build().map_err(anyhow::Error::msg)?;
        Ok(Self {
            name: format!("{trial} {}", c.name()),
            trial,
            controller,
            gains,
            trajectory,
            force,
            surface,
        })
    }
}

struct Outcome {
    run: RunOutput,
    plan: ElbowPlan,
    singular_samples: usize,
    tracking: TrackingSummary<4>,
    force: Option<ForceSummary>,
    controller_name: &'static str,
}

/// Plans the elbows over the whole reference (refusing unreachable samples before any
/// simulation), then simulates.
fn execute(spec: &mut Spec<'_>, sim: &SimArgs) -> anyhow::Result<Outcome> {
    let duration = spec.trajectory.duration();
    sim.limit
        .check_run(&spec.name, duration, sim.control_dt, sim.plant_dt)?;
    let geometry = ScaraGeometry::from_model(&Scara);
    let plan = geometry
        .plan_trajectory(
            spec.trajectory,
            0.005_f64.min(sim.control_dt.max(1e-6)),
            SwitchPolicy::Latest,
        )
        .with_context(|| {
            format!(
                "{}: the reference leaves the workspace; nothing was simulated",
                spec.name
            )
        })?;
    let mut reference = ScaraReference::new(geometry, spec.trajectory, plan.clone(), spec.force);
    let mut config = SimConfig::thesis(&Scara);
    config.duration = spec.trajectory.duration();
    config.control_dt = sim.control_dt;
    config.plant_dt = sim.plant_dt;
    config.q0 = nalgebra::Vector4::from(crate::cli_args::joint_values::<4>(
        "--q0",
        "scara",
        sim.q0.as_ref(),
    )?);
    let surface = ReactionSurface::thesis();
    let environment: &dyn Environment = match spec.surface {
        Surface::None => &FreeSpace,
        Surface::Thesis => &surface,
    };
    let mut progress = crate::progress::Progress::start(&spec.name, 0.0, config.duration);
    let run_out = run(
        &Scara,
        spec.controller.as_mut(),
        &mut reference,
        environment,
        &config,
        |t| progress.update(t),
    )
    .with_context(|| format!("{}: simulation stopped; no files were written", spec.name))?;
    progress.finish();
    let mut tracking = TrackingMetrics::new(2.0);
    let mut force = spec.force.map(|_| ForceMetrics::thesis());
    for s in &run_out.samples {
        tracking.push(s);
        if let Some(f) = force.as_mut() {
            f.push(s);
        }
    }
    Ok(Outcome {
        controller_name: spec.controller.name(),
        singular_samples: reference.singular_samples(),
        plan,
        tracking: tracking.summary(),
        force: force.map(|f| f.summary()),
        run: run_out,
    })
}

fn surface_patch(surface: Surface) -> Option<SurfacePatch> {
    match surface {
        Surface::None => None,
        Surface::Thesis => {
            let s = ReactionSurface::thesis();
            Some(SurfacePatch {
                z: s.height(),
                x_range: s.x_range(),
                y_range: s.y_range(),
            })
        }
    }
}

fn metrics_json(spec: &Spec<'_>, r: &Outcome) -> Value {
    let t = &r.tracking;
    let g = &spec.gains;
    let mut gains = serde_json::Map::new();
    if let Some(v) = g.kp {
        gains.insert("kp".into(), json!(v));
    }
    if let Some(v) = g.ki {
        gains.insert("ki".into(), json!(v));
    }
    if let Some(v) = g.kd {
        gains.insert("kd".into(), json!(v));
    }
    if let Some(v) = g.k1 {
        gains.insert("k1".into(), json!(v));
    }
    if let Some(v) = g.k2 {
        gains.insert("k2".into(), json!(v));
    }
    if !g.poles.is_empty() {
        gains.insert("poles".into(), json!(g.poles));
    }
    if let Some(v) = g.riccati_residual {
        gains.insert("riccati_residual".into(), json!(v));
    }
    if let Some((kfp, kfi, kvd)) = g.force {
        gains.insert("kfp".into(), json!(kfp));
        gains.insert("kfi".into(), json!(kfi));
        gains.insert("kvd".into(), json!(kvd));
    }
    gains.insert("note".into(), json!(g.note));
    let stats = &r.run.stats;
    let mut m = json!({
        "trial": spec.trial,
        "controller": r.controller_name,
        "gains": gains,
        "units": "joint errors in rad (q1, q2, q4) and m (d3); torques in N m (q1, q2, q4) and N (d3)",
        "rms_joint_error": t.rms_joint_error.as_slice(),
        "rms_joint_error_after_2s": t.rms_joint_error_after.as_slice(),
        "max_joint_error_after_2s": t.max_joint_error_after.as_slice(),
        "max_abs_tau": t.max_abs_tau.as_slice(),
        "saturated_samples": stats.saturated_samples,
        "first_joint_limit_violation_s": stats.first_limit_violation,
        "singular_reference_samples": r.singular_samples,
        "elbow": {
            "initial": r.plan.initial().to_string(),
            "switches_s": r.plan.switches().iter().map(|s| s.t).collect::<Vec<_>>(),
        },
        "samples": stats.samples,
    });
    if let Some(f) = &r.force {
        let obj = m.as_object_mut().expect("an object");
        obj.insert("force_overshoot_pct".into(), json!(f.force_overshoot_pct));
        obj.insert("settling_time_s".into(), json!(f.settling_time_s));
        obj.insert(
            "force_rms_error_last5s_n".into(),
            json!(f.force_rms_error_last_n),
        );
        obj.insert(
            "xy_rms_error_contact_mm".into(),
            json!(f.xy_rms_error_contact_mm),
        );
        obj.insert("min_z_m".into(), json!(f.min_z_m));
    }
    m
}

/// Writes every output file of a run into `dir`, all or nothing.
fn write(dir: &Path, spec: &Spec<'_>, r: &Outcome) -> anyhow::Result<()> {
    let samples = &r.run.samples;
    let mut out =
        OutputDir::create(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    out.write(
        "trajectory.csv",
        report::trajectory_csv(samples, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS),
    )?;
    let metrics = serde_json::to_string_pretty(&metrics_json(spec, r))?;
    out.write("metrics.json", metrics + "\n")?;
    let patch = surface_patch(spec.surface);
    out.write("path.svg", report::path_views(samples, patch.as_ref())?)?;
    out.write(
        "joints.svg",
        report::joint_tracking(samples, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS)?,
    )?;
    out.write(
        "joint_errors.svg",
        report::joint_errors(samples, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS, None)?,
    )?;
    out.write(
        "joint_errors_first_2s.svg",
        report::joint_errors(
            samples,
            &Scara::JOINT_NAMES,
            &Scara::JOINT_KINDS,
            Some((0.0, 2.0)),
        )?,
    )?;
    out.write("cartesian.svg", report::cartesian_tracking(samples)?)?;
    if spec.force.is_some() || matches!(spec.surface, Surface::Thesis) {
        out.write("force.svg", report::force_tracking(samples)?)?;
    }
    out.commit()
        .with_context(|| format!("cannot write into {}", dir.display()))?;
    Ok(())
}

fn print_single(spec: &Spec<'_>, r: &Outcome, dir: &Path) {
    let t = &r.tracking;
    let mut table = Table::new(["metric", "q1", "q2", "d3", "q4"]);
    let row = |name: &str, v: &[f64]| {
        std::iter::once(name.to_string())
            .chain(v.iter().map(|x| format!("{x:.3e}")))
            .collect::<Vec<_>>()
    };
    table.push_row(row("RMS error (rad, m)", t.rms_joint_error.as_slice()));
    table.push_row(row(
        "RMS error after 2 s",
        t.rms_joint_error_after.as_slice(),
    ));
    table.push_row(row(
        "max |error| after 2 s",
        t.max_joint_error_after.as_slice(),
    ));
    table.push_row(row("max |tau| (N m, N)", t.max_abs_tau.as_slice()));
    println!(
        "{} ({} samples)\n\n{}",
        spec.name,
        r.run.stats.samples,
        table.markdown()
    );
    if let Some(f) = &r.force {
        let mut ft = Table::new(["force metric", "value"]);
        ft.push_row([
            "overshoot beyond the reference after 2 s (% of 200 N)".to_string(),
            format!("{:.2}", f.force_overshoot_pct),
        ]);
        ft.push_row([
            "settling time after 2 s, 5 % band (s)".to_string(),
            f.settling_time_s
                .map_or("not settled".into(), |s| format!("{s:.3}")),
        ]);
        ft.push_row([
            "RMS force error, last 5 s (N)".to_string(),
            format!("{:.3}", f.force_rms_error_last_n),
        ]);
        ft.push_row([
            "x-y RMS error in contact (mm)".to_string(),
            format!("{:.3}", f.xy_rms_error_contact_mm),
        ]);
        ft.push_row(["lowest tool z (m)".to_string(), format!("{:.4}", f.min_z_m)]);
        println!("{}", ft.markdown());
    }
    if !r.plan.switches().is_empty() {
        let s: Vec<String> = r
            .plan
            .switches()
            .iter()
            .map(|s| format!("{:.3} s -> {}", s.t, s.to))
            .collect();
        println!(
            "elbow: starts {}, switches at {}",
            r.plan.initial(),
            s.join(", ")
        );
    }
    println!("wrote {}/: trajectory.csv, metrics.json, path.svg, joints.svg, joint_errors*.svg, cartesian.svg{}", dir.display(), if matches!(spec.surface, Surface::Thesis) { ", force.svg" } else { "" });
}
