//! `armdyn identify --log FILE`: identification of a robot from its own recorded log, validated
//! on held-out data, with progress of its stages and their times; `--write-description DIR`
//! turns the result into a robot description. The companions `--excitation-only` and
//! `--write-log FILE` are in [`super::identify_companions`].

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context;
use clap::{Args, ValueEnum};
use serde_json::{json, Value};

use armdyn::identification::description_out::describe;
use armdyn::identification::friction_model::FrictionModel;
use armdyn::identification::from_log::{
    identify_log_observed, LogIdentification, LogIdentifySettings,
};
use armdyn::identification::log::{JointLog, LogReport, LogSettings};
use armdyn::identification::physical::{smallest_eigenvalue, ConsistentFit, ConsistentSolver};
use armdyn::identification::stages::{Event, Stage};
use armdyn::identification::unmodelled::Unmodelled;
use armdyn::identification::{Identifiable, PER_LINK};
use armdyn::model::{JointKind, ParametricModel, RobotModel};
use armdyn::report::data_plots::{scatter_panels, time_panels, Panel};
use armdyn::report::{OutputDir, Table};

use super::cli_args::OnOff;
use super::identify_companions::{excitation_only, write_log, Common, LogOptions};
use super::stage_progress::{times_line, CountingReader, StageProgress};

/// Friction model fitted to a log.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FrictionChoice {
    /// No friction.
    None,
    /// `fv qd + fc sign(qd)`.
    ViscousCoulomb,
    /// `fv qd + fc tanh(qd / v)`, the slope `v` fitted per joint.
    Smooth,
}

/// Solver of the consistent fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SolverChoice {
    /// Interior point: log barrier, Newton steps; stops with the cost certified within
    /// 1e-10 of the constrained minimum.
    Barrier,
    /// Levenberg-Marquardt in the log-Cholesky parameters; stops on the relative change of the
    /// cost or of the step.
    LogCholesky,
}

/// The options of identification from a log (and its companions).
#[derive(Debug, Args)]
pub struct LogArgs {
    /// Identify from this log (CSV: t, q1..qN, optional qd1..qdN, tau1..tauN; SI units).
    #[arg(long, value_name = "FILE")]
    log: Option<PathBuf>,
    /// Validate on this log (default: the held-out end of --log).
    #[arg(long, value_name = "FILE")]
    validate: Option<PathBuf>,
    /// Part of --log held out for validation, from its end (when --validate is not given).
    #[arg(long, default_value_t = 0.25, value_name = "FRACTION")]
    holdout: f64,
    /// Friction model fitted.
    #[arg(long, value_enum, default_value_t = FrictionChoice::Smooth)]
    friction_model: FrictionChoice,
    /// A constant torque offset per joint, fitted.
    #[arg(long, value_enum, default_value_t = OnOff::On)]
    offset: OnOff,
    /// Physically consistent standard parameters.
    #[arg(long, value_enum, default_value_t = OnOff::On)]
    consistent: OnOff,
    /// Solver of the consistent fit: an interior-point (log-barrier) method, or
    /// Levenberg-Marquardt in the log-Cholesky parameters.
    #[arg(long, value_enum, default_value_t = SolverChoice::Barrier)]
    consistent_solver: SolverChoice,
    /// Uniform resampling rate, Hz (default: the log's median rate).
    #[arg(long, value_name = "HZ")]
    rate_hz: Option<f64>,
    /// Low-pass cutoff, Hz (default: 5 x the positions' bandwidth).
    #[arg(long, value_name = "HZ")]
    cutoff_hz: Option<f64>,
    /// Butterworth filter order.
    #[arg(long, default_value_t = 4, value_name = "N")]
    filter_order: usize,
    /// Longest interval bridged by interpolation, s (default 10 median intervals); longer
    /// gaps split the log into segments.
    #[arg(long, value_name = "S")]
    max_gap_s: Option<f64>,
    /// Position jump between two samples reported, rad or m.
    #[arg(long, default_value_t = 0.2, value_name = "X")]
    jump_threshold: f64,
    /// Write the identified robot description (<NAME>.toml and <NAME>.urdf) into DIR (for
    /// `bash codegen/regenerate.sh`: use the robots/ folder).
    #[arg(long, value_name = "DIR")]
    write_description: Option<PathBuf>,
    /// Name of the identified robot (default <robot>_identified).
    #[arg(long, value_name = "NAME")]
    name: Option<String>,
    /// Only design the excitation and write it (excitation.csv) into --out.
    #[arg(long)]
    excitation_only: bool,
    /// Sample rate of the written excitation, Hz.
    #[arg(long, default_value_t = 1000.0, value_name = "HZ")]
    excitation_rate_hz: f64,
    /// Make an example log on the simulated plant (one excitation period, --noise-pct and
    /// --friction as set, jitter, lost samples, a gap, duplicated and NaN rows, a torque offset)
    /// and write it to FILE.
    #[arg(long, value_name = "FILE")]
    write_log: Option<PathBuf>,
    /// Length of the --write-log log, s (the excitation repeated; default one period).
    #[arg(long, value_name = "S")]
    log_seconds: Option<f64>,
    /// In the --write-log plant, link L's inertia breaks the triangle inequality (its largest
    /// principal moment 1.3 times the sum of the other two): true parameters outside the
    /// physically consistent set.
    #[arg(long, value_name = "L")]
    break_link: Option<usize>,
    /// In the --write-log plant, friction the fitted models lack on top of --friction on: a
    /// Stribeck term (half the Coulomb level at rest, over 0.1 rad/s) and a Coulomb level 20 %
    /// higher one way than the other.
    #[arg(long)]
    unmodelled_friction: bool,
    /// Samples lost in the --write-log log, %.
    #[arg(long, default_value_t = 1.0, value_name = "P")]
    lost_pct: f64,
}

impl LogArgs {
    /// Whether any of these modes is asked for.
    pub fn active(&self) -> bool {
        self.log.is_some() || self.excitation_only || self.write_log.is_some()
    }
}

/// Runs the mode `a` asks for on `robot`, whose generated URDF is `urdf`.
pub fn run<const N: usize, R: Identifiable<N> + ParametricModel<N>>(
    robot: &R,
    urdf: &str,
    a: &LogArgs,
    common: &Common<'_>,
) -> anyhow::Result<()> {
    if a.excitation_only {
        return excitation_only(robot, a.excitation_rate_hz, common);
    }
    if let Some(path) = &a.write_log {
        let options = LogOptions {
            seconds: a.log_seconds,
            lost_pct: a.lost_pct,
            unmodelled: Unmodelled {
                broken_link: a.break_link,
                friction: a.unmodelled_friction,
            },
        };
        return write_log(robot, path, &options, common);
    }
    let Some(path) = &a.log else {
        anyhow::bail!("no mode: give --log, --excitation-only or --write-log");
    };
    from_log(robot, urdf, path, a, common)
}

fn read_log<const N: usize>(
    path: &Path,
    a: &LogArgs,
    progress: &mut StageProgress,
) -> anyhow::Result<(JointLog<N>, LogReport)> {
    let file =
        std::fs::File::open(path).with_context(|| format!("cannot open {}", path.display()))?;
    let size = file.metadata().ok().map(|m| m.len());
    let settings = LogSettings {
        jump_threshold: a.jump_threshold,
        ..LogSettings::default()
    };
    let counted = CountingReader::new(file, |done| {
        progress.event(Event::Progress {
            done,
            of: size,
            unit: "bytes",
        });
    });
    JointLog::<N>::from_csv_reader(std::io::BufReader::new(counted), &settings)
        .with_context(|| format!("{}: not a usable log of a {N}-joint robot", path.display()))
}

fn unit<const N: usize, R: RobotModel<N>>(i: usize) -> &'static str {
    match R::JOINT_KINDS.get(i) {
        Some(JointKind::Prismatic) => "N",
        _ => "N m",
    }
}

fn from_log<const N: usize, R: Identifiable<N>>(
    robot: &R,
    urdf: &str,
    path: &Path,
    a: &LogArgs,
    common: &Common<'_>,
) -> anyhow::Result<()> {
    let name = a
        .name
        .clone()
        .unwrap_or_else(|| format!("{}_identified", R::NAME));
    let mut progress = StageProgress::stderr();
    let reading = Instant::now();
    progress.event(Event::Start(Stage::Reading));
    let (log, report) = read_log::<N>(path, a, &mut progress)?;
    outln!("{}: {report}", path.display());
    let (estimation, validation) = match &a.validate {
        Some(v) => {
            let (vlog, vreport) = read_log::<N>(v, a, &mut progress)?;
            outln!("{}: {vreport}", v.display());
            (log, vlog)
        }
        None => {
            if !(a.holdout.is_finite() && a.holdout > 0.0 && a.holdout < 1.0) {
                anyhow::bail!("--holdout {}: must be in (0, 1)", a.holdout);
            }
            let (t0, t1) = (log.t[0], log.t[log.t.len() - 1]);
            let split = t1 - a.holdout * (t1 - t0);
            let e = log.slice_time(t0, split);
            let v = log.slice_time(split, f64::INFINITY);
            (e, v)
        }
    };
    let settings = LogIdentifySettings {
        process: armdyn::identification::processing::ProcessSettings {
            rate_hz: a.rate_hz,
            cutoff_hz: a.cutoff_hz,
            order: a.filter_order,
            max_gap_s: a.max_gap_s,
        },
        friction: match a.friction_model {
            FrictionChoice::None => FrictionModel::None,
            FrictionChoice::ViscousCoulomb => FrictionModel::ViscousCoulomb,
            FrictionChoice::Smooth => FrictionModel::Smooth,
        },
        offset: a.offset == OnOff::On,
        consistent: a.consistent == OnOff::On,
        solver: match a.consistent_solver {
            SolverChoice::Barrier => ConsistentSolver::Barrier,
            SolverChoice::LogCholesky => ConsistentSolver::LogCholesky,
        },
        seed: common.settings.seed,
    };
    let mut times = vec![(Stage::Reading, reading.elapsed().as_secs_f64())];
    progress.event(Event::Finish(Stage::Reading, times[0].1));
    let id = identify_log_observed(robot, &estimation, &validation, &settings, &mut |e| {
        progress.event(e);
    })
    .with_context(|| {
        format!(
            "identifying {} from {}: nothing was written",
            R::NAME,
            path.display()
        )
    })?;
    times.extend(id.timings.iter().copied());
    let drawing = Instant::now();
    progress.event(Event::Start(Stage::Figures));
    let validation_svg = validation_figure::<N, R>(&id)?;
    let friction_svg = if id.terms.per_joint() > 0 {
        Some(friction_figure::<N, R>(&id)?)
    } else {
        None
    };
    times.push((Stage::Figures, drawing.elapsed().as_secs_f64()));
    progress.event(Event::Finish(Stage::Figures, 0.0));
    let dir = common.out.map_or_else(
        || PathBuf::from(format!("out/identify-{}-log", R::NAME)),
        Path::to_path_buf,
    );
    let mut out =
        OutputDir::create(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let value = log_json(&id, &report, path, &times);
    out.write(
        "identification.json",
        serde_json::to_string_pretty(&value)? + "\n",
    )?;
    out.write("validation_torques.svg", validation_svg)?;
    if let Some(svg) = friction_svg {
        out.write("friction.svg", svg)?;
    }
    out.commit()
        .with_context(|| format!("cannot write into {}", dir.display()))?;
    print::<N, R>(&id);
    outln!("time: {}", times_line(&times));
    outln!(
        "wrote {}/: identification.json, validation_torques.svg{}",
        dir.display(),
        if id.terms.per_joint() > 0 {
            ", friction.svg"
        } else {
            ""
        }
    );
    if let Some(target) = &a.write_description {
        let n = N;
        let fv: Vec<f64>;
        let fc: Vec<f64>;
        let friction = if id.terms.model == FrictionModel::None {
            None
        } else {
            fv = id.friction.as_slice()[..n].to_vec();
            fc = id.friction.as_slice()[n..2 * n].to_vec();
            Some((fv.as_slice(), fc.as_slice()))
        };
        let note = format!(
            "{name}: {} identified from the log {} by `armdyn identify` ({} friction{}, {} standard parameters). The inertias are the identification's; <dynamics damping friction> hold the viscous and Coulomb coefficients{}.",
            R::NAME,
            path.file_name().map_or_else(|| path.display().to_string(), |f| f.to_string_lossy().into_owned()),
            id.terms.model.name(),
            if id.terms.offset { " and a torque offset" } else { "" },
            if id.consistent.is_some() { "physically consistent" } else { "unconstrained (not checked for consistency)" },
            if id.terms.model == FrictionModel::Smooth {
                format!(" (Coulomb smoothed as tanh(qd / v), v = {:?} rad/s or m/s)", id.terms.slopes)
            } else {
                String::new()
            }
        );
        let d = describe(robot, urdf, &name, id.standard.as_slice(), friction, &note)?;
        std::fs::create_dir_all(target)
            .with_context(|| format!("cannot create {}", target.display()))?;
        let mut o = OutputDir::create(target)
            .with_context(|| format!("cannot write into {}", target.display()))?;
        o.write(format!("{name}.toml"), d.toml)?;
        o.write(format!("{name}.urdf"), d.urdf)?;
        o.commit()
            .with_context(|| format!("cannot write into {}", target.display()))?;
        outln!(
            "wrote {}/{name}.toml and {name}.urdf: regenerate with `bash codegen/regenerate.sh` (when written into robots/)",
            target.display()
        );
    }
    Ok(())
}

fn error_json(e: &armdyn::identification::from_log::TorqueError) -> Value {
    json!({"rms": e.rms, "pct_of_rms_torque": e.pct, "rms_against_filtered": e.rms_filtered})
}

fn log_json<const N: usize>(
    id: &LogIdentification<N>,
    report: &LogReport,
    path: &Path,
    times: &[(Stage, f64)],
) -> Value {
    let mut timings: serde_json::Map<String, Value> =
        times.iter().map(|(s, t)| (s.key(), json!(t))).collect();
    timings.insert(
        "total".into(),
        json!(times.iter().map(|(_, t)| t).sum::<f64>()),
    );
    let names = id.base.parameter_names();
    let p = PER_LINK * N;
    let standard: serde_json::Map<String, Value> = names[..p]
        .iter()
        .zip(id.standard.iter())
        .map(|(n, v)| (n.clone(), json!(v)))
        .collect();
    let friction: serde_json::Map<String, Value> = id
        .terms
        .names()
        .iter()
        .zip(id.friction.iter())
        .map(|(n, v)| (n.clone(), json!(v)))
        .collect();
    let process = |r: &armdyn::identification::processing::ProcessReport| {
        json!({
            "rate_hz": r.rate_hz, "cutoff_hz": r.cutoff_hz, "bandwidth_hz": r.bandwidth_hz,
            "filter_order": r.order, "trim_samples": r.trim_samples, "max_gap_s": r.max_gap_s,
            "segments_s": r.segments, "dropped_segments_s": r.dropped_segments,
            "measured_velocities": r.measured_velocities,
        })
    };
    json!({
        "robot": id.robot,
        "log": path.display().to_string(),
        "log_report": report.to_string(),
        "units": "SI: kg, kg m, kg m^2 (inertia about each link frame's origin); fv N m s/rad or N s/m, fc and fo N m or N; torques N m or N",
        "estimation_processing": process(&id.estimation_report),
        "validation_processing": process(&id.validation_report),
        "estimation_samples": id.estimation_samples,
        "decimation": id.decimation,
        "friction_model": id.terms.model.name(),
        "torque_offset": id.terms.offset,
        "coulomb_slopes": id.terms.slopes,
        "base_parameter_names": id.base.names(),
        "base_parameters_unconstrained": id.estimate.weighted.as_slice(),
        "base_parameters_relative_std_pct": id.estimate.relative_std_pct,
        "base_parameters_identified": id.base_of_identified.as_slice(),
        "residual_std": id.estimate.residual_std,
        "physically_consistent": id.consistent.is_some(),
        "smallest_pseudo_inertia_eigenvalues": (0..N).map(|l| smallest_eigenvalue(&id.standard.as_slice()[l * PER_LINK..(l + 1) * PER_LINK])).collect::<Vec<_>>(),
        "solver": id.consistent.as_ref().map(solver_json),
        "standard_parameters": standard,
        "friction": friction,
        "prior": "the description's standard parameters (made consistent where they are not), weight 1e-3 against the weighted data residual",
        "timings_s": timings,
        "validation": {
            "samples": id.validation.len(),
            "identified": error_json(&id.error),
            "unconstrained_base": error_json(&id.error_unconstrained),
            "nominal": error_json(&id.error_nominal),
        },
    })
}

fn solver_json(c: &ConsistentFit) -> Value {
    let stop = c.solver.stopping();
    json!({
        "method": c.solver.name(),
        "status": c.status.name(),
        "converged": c.status.converged(),
        "stopped_by": c.solution.termination.to_string(),
        "evaluations": c.solution.evaluations,
        "budget": c.solution.budget,
        "derivative_evaluations": c.solution.derivatives,
        "cost_tolerance": stop.cost_tolerance,
        "step_tolerance": stop.step_tolerance,
        "initial_cost": c.solution.initial_cost,
        "cost": c.solution.cost,
        "unconstrained_cost": c.unconstrained.cost,
        "cost_ratio_to_unconstrained": c.cost_ratio,
        "links_outside_when_unconstrained": c.unconstrained.outside.iter().map(|(l, e)| json!({"link": l, "smallest_pseudo_inertia_eigenvalue": e})).collect::<Vec<_>>(),
    })
}

/// The consistent fit's line: the solver's status, its evaluations of the budget, and how far
/// it is from the unconstrained fit.
fn solver_line(c: &ConsistentFit) -> String {
    let mut line = format!(
        "consistent fit ({}): {} after {} of {} evaluations ({} {}), stopped by {}; smallest pseudo-inertia eigenvalue {:.3e}",
        c.solver.name(),
        c.status,
        c.solution.evaluations,
        c.solution.budget,
        c.solution.derivatives,
        match c.solver {
            ConsistentSolver::Barrier => "Newton steps",
            ConsistentSolver::LogCholesky => "Jacobians",
        },
        c.solution.termination.rule(),
        c.smallest_eigenvalues.iter().copied().fold(f64::INFINITY, f64::min),
    );
    for (l, e) in &c.unconstrained.outside {
        line.push_str(&format!(
            "\n  link {l}: the data push it past the boundary (unconstrained, its smallest pseudo-inertia eigenvalue is {e:.3e}: no rigid body)"
        ));
    }
    line.push_str(&format!(
        "\n  cost {:.6e}, {:.6} x the unconstrained fit's ({:+.2e} relative)",
        c.solution.cost,
        c.cost_ratio,
        c.cost_ratio - 1.0
    ));
    line
}

fn print<const N: usize, R: RobotModel<N>>(id: &LogIdentification<N>) {
    outln!("estimation: {}", id.estimation_report);
    outln!(
        "{}: {} base parameters (of {}) from {} samples (decimation {}), friction {}{}",
        id.robot,
        id.base.count(),
        id.base.parameter_names().len(),
        id.estimation_samples,
        id.decimation,
        id.terms.model.name(),
        if id.terms.offset { " + offset" } else { "" }
    );
    if id.terms.model == FrictionModel::Smooth {
        outln!(
            "smooth Coulomb slopes v (rad/s or m/s): {}",
            id.terms
                .slopes
                .iter()
                .map(|v| format!("{v:.4}"))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    match &id.consistent {
        Some(c) => outln!(
            "physically consistent: every link's pseudo-inertia positive definite\n{}",
            solver_line(c)
        ),
        None => outln!("physical consistency not imposed (--consistent off)"),
    }
    let mut t = Table::new([
        "joint",
        "RMS torque",
        "identified: RMS error",
        "%",
        "unconstrained: %",
        "nominal: RMS error",
        "%",
    ]);
    for i in 0..N {
        let scale = id.error.rms[i] / (id.error.pct[i] / 100.0);
        t.push_row([
            format!("{}", i + 1),
            format!("{scale:.3} {}", unit::<N, R>(i)),
            format!("{:.4} {}", id.error.rms[i], unit::<N, R>(i)),
            format!("{:.2}", id.error.pct[i]),
            format!("{:.2}", id.error_unconstrained.pct[i]),
            format!("{:.4} {}", id.error_nominal.rms[i], unit::<N, R>(i)),
            format!("{:.2}", id.error_nominal.pct[i]),
        ]);
    }
    outln!(
        "validation on {} held-out samples ({:.2} s), errors against the logged torques:\n{}",
        id.validation.len(),
        id.validation.len() as f64 / id.validation_report.rate_hz,
        t.markdown()
    );
}

fn validation_figure<const N: usize, R: RobotModel<N>>(
    id: &LogIdentification<N>,
) -> anyhow::Result<String> {
    let v = &id.validation;
    let series = |f: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
        v.t.iter().enumerate().map(|(k, t)| (*t, f(k))).collect()
    };
    let panels: Vec<Panel> = (0..N)
        .map(|i| Panel {
            title: format!(
                "joint {}: RMS error identified {:.2} %, nominal {:.2} % of the RMS torque",
                i + 1,
                id.error.pct[i],
                id.error_nominal.pct[i]
            ),
            y_label: format!("tau{} ({})", i + 1, unit::<N, R>(i)),
            series: vec![
                ("logged".into(), series(&|k| v.tau_raw[k][i])),
                ("identified model".into(), series(&|k| id.predicted[k][i])),
                (
                    "nominal model".into(),
                    series(&|k| id.predicted_nominal[k][i]),
                ),
            ],
        })
        .collect();
    Ok(time_panels(
        &format!("{}: held-out torques, logged and predicted", id.robot),
        &panels,
    )?)
}

fn friction_figure<const N: usize, R: RobotModel<N>>(
    id: &LogIdentification<N>,
) -> anyhow::Result<String> {
    let panels: Vec<Panel> = (0..N)
        .map(|i| {
            let pts = &id.friction_residual[i];
            let (lo, hi) = pts
                .iter()
                .fold((0.0f64, 0.0f64), |(l, h), (v, _)| (l.min(*v), h.max(*v)));
            let curve: Vec<(f64, f64)> = (0..=400)
                .map(|k| {
                    let v = lo + (hi - lo) * f64::from(k) / 400.0;
                    (v, id.terms.torque(id.friction.as_slice(), i, v))
                })
                .collect();
            Panel {
                title: format!("joint {}: residual torque and the fitted friction", i + 1),
                y_label: format!("tau{} - Y pi ({})", i + 1, unit::<N, R>(i)),
                series: vec![
                    (
                        "logged torque minus the rigid-body model".into(),
                        pts.clone(),
                    ),
                    (format!("fitted {}", id.terms.model.name()), curve),
                ],
            }
        })
        .collect();
    Ok(scatter_panels(
        &format!("{}: joint friction against velocity", id.robot),
        "joint velocity (rad/s or m/s)",
        &panels,
    )?)
}
