//! `scara run joint-reference`: any generated robot tracks a joint trajectory from a CSV file
//! (`t,q1..qn`) in free space, with computed torque or PID with feedback linearization; writes
//! `trajectory.csv`, `metrics.json` and SVG figures like the other trials.

use std::path::PathBuf;

use anyhow::Context;
use clap::{Args, ValueEnum};
use nalgebra::Vector3;
use serde_json::json;

use scara::contact::FreeSpace;
use scara::control::computed_torque::ComputedTorque;
use scara::control::gains::MassRounding;
use scara::control::mass_split::SplitKind;
use scara::control::pid_fl::PidFeedbackLinearization;
use scara::control::Controller;
use scara::metrics::TrackingMetrics;
use scara::model::{visit_robot, RobotModel, RobotVisitor, Wrench};
use scara::report::{self, OutputDir};
use scara::sim::{simulate, ReferenceSource, Sample, Setpoint, SimConfig};
use scara::target::CartesianTarget;
use scara::trajectory::JointReference;

use crate::cli_args::robot_parser;

/// The joint-space controllers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum JointController {
    /// `tau = M (qdd_d + Kp e + Kd e') + c + g`, critically damped at `--omega`.
    ComputedTorque,
    /// The thesis's PID with feedback linearization (poles -8, -9, -10 on the diagonal of the
    /// constant part of M).
    PidFl,
}

/// Arguments of `scara run joint-reference`.
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
}

struct Source<'a, const N: usize, R> {
    reference: &'a JointReference<N>,
    robot: &'a R,
}

impl<const N: usize, R: RobotModel<N>> ReferenceSource<N> for Source<'_, N, R> {
    fn at(&mut self, t: f64) -> Setpoint<N> {
        let joint = self.reference.at(t);
        let pose = self.robot.end_effector_pose(&joint.q);
        let mut cartesian = CartesianTarget::at_rest(
            Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]),
            scara::target::orientation::of_pose(&pose),
        );
        let twist = self.robot.jacobian(&joint.q) * joint.qd;
        cartesian.velocity = Vector3::new(twist[0], twist[1], twist[2]);
        cartesian.angular_velocity = Vector3::new(twist[3], twist[4], twist[5]);
        Setpoint {
            joint,
            cartesian,
            wrench: Wrench::zeros(),
        }
    }
}

struct Trial<'a>(&'a JointReferenceArgs);

impl RobotVisitor for Trial<'_> {
    type Output = anyhow::Result<()>;

    fn visit<const N: usize, R: RobotModel<N> + Copy + 'static>(
        self,
        robot: &R,
    ) -> anyhow::Result<()> {
        let args = self.0;
        let file = std::fs::File::open(&args.csv)
            .with_context(|| format!("opening {}", args.csv.display()))?;
        let reference = JointReference::<N>::from_csv_reader(std::io::BufReader::new(file))
            .with_context(|| format!("{} (robot {}, {N} joints)", args.csv.display(), R::NAME))?;
        let mut controller: Box<dyn Controller<N>> = match args.controller {
            JointController::ComputedTorque => {
                anyhow::ensure!(
                    args.omega.is_finite() && args.omega > 0.0,
                    "--omega must be a positive number of rad/s"
                );
                Box::new(ComputedTorque::critically_damped(*robot, args.omega))
            }
            JointController::PidFl => Box::new(
                PidFeedbackLinearization::thesis(
                    *robot,
                    SplitKind::ConstantPart,
                    MassRounding::Exact,
                )
                .context("the constant part of M is singular")?,
            ),
        };
        let start = reference.at(0.0);
        let config = SimConfig {
            duration: reference.duration(),
            plant_dt: args.dt,
            control_dt: args.dt,
            q0: start.q,
            qd0: start.qd,
            ..SimConfig::thesis(robot)
        };
        let mut source = Source {
            reference: &reference,
            robot,
        };
        let mut samples: Vec<Sample<N>> = Vec::new();
        let mut metrics = TrackingMetrics::<N>::new(args.after);
        let stats = simulate(
            robot,
            &mut *controller,
            &mut source,
            &FreeSpace,
            &config,
            |s| {
                metrics.push(s);
                samples.push(*s);
            },
        )
        .with_context(|| format!("simulating {} with {}", R::NAME, controller.name()))?;
        let summary = metrics.summary();
        let max_after = summary.max_joint_error_after.amax();
        let out = args
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from(format!("out/joint-reference-{}", R::NAME)));
        let metrics_json = json!({
            "robot": R::NAME,
            "controller": controller.name(),
            "reference": args.csv.display().to_string(),
            "duration_s": reference.duration(),
            "dt_s": args.dt,
            "after_s": args.after,
            "max_joint_error_after": summary.max_joint_error_after.as_slice(),
            "max_abs_joint_error_after": max_after,
            "rms_joint_error_after": summary.rms_joint_error_after.as_slice(),
            "rms_joint_error": summary.rms_joint_error.as_slice(),
            "max_abs_tau": summary.max_abs_tau.as_slice(),
            "saturated_samples": stats.saturated_samples.as_slice(),
            "samples": stats.samples,
        });
        let mut dir =
            OutputDir::create(&out).with_context(|| format!("creating {}", out.display()))?;
        let names = R::JOINT_NAMES;
        let kinds = R::JOINT_KINDS;
        dir.write(
            "trajectory.csv",
            report::trajectory_csv(&samples, &names, &kinds),
        )?;
        dir.write(
            "metrics.json",
            serde_json::to_string_pretty(&metrics_json)? + "\n",
        )?;
        dir.write(
            "joint_tracking.svg",
            report::joint_tracking(&samples, &names, &kinds)?,
        )?;
        dir.write(
            "joint_errors.svg",
            report::joint_errors(&samples, &names, &kinds, None)?,
        )?;
        let written = dir
            .commit()
            .with_context(|| format!("writing {}", out.display()))?;
        outln!(
            "{} with {}: max |joint error| after {} s = {:.3e} (rad or m); wrote {} files to {}",
            R::NAME,
            controller.name(),
            args.after,
            max_after,
            written.len(),
            out.display()
        );
        Ok(())
    }
}

/// Runs `scara run joint-reference`.
pub fn run(args: &JointReferenceArgs) -> anyhow::Result<()> {
    visit_robot(&args.robot, Trial(args))
        .with_context(|| format!("unknown robot '{}'", args.robot))?
}
