//! `armdyn simulate [--robot NAME] --torque-csv FILE --out DIR`: open-loop simulation of any
//! generated robot (the SCARA by default).

use std::path::PathBuf;

use anyhow::Context;
use clap::Args;

use armdyn::model::{JointVector, RobotModel};
use armdyn::report::OutputDir;
use armdyn::sim::open_loop::{plant_steps, simulate_torques};
use armdyn::sim::torque_history::TorqueHistory;
use armdyn::sim::EndStops;

use crate::cli_args::{joint_list, parse_number_list, robot_parser, NumberList};
use crate::progress::{num, Progress, StepLimit};

/// Arguments of `armdyn simulate`.
#[derive(Debug, Args)]
pub struct SimulateArgs {
    /// Robot (any generated robot).
    #[arg(long, value_parser = robot_parser(), default_value = "scara")]
    robot: String,
    /// Torques: CSV with header `t,tau1,...,tauN` (s; N m for a revolute joint, N for a
    /// prismatic one), strictly increasing t; each row is held until the next one. UTF-8, with
    /// or without a byte-order mark, LF or CRLF line ends.
    #[arg(long, value_name = "FILE")]
    torque_csv: PathBuf,
    /// Output folder; gets `trajectory.csv` (`t,q1,...,qN,qd1,...,qdN`).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Initial joint positions (default: home, all zero), rad and m.
    #[arg(long, value_parser = parse_number_list, allow_hyphen_values = true)]
    q0: Option<NumberList>,
    /// Initial joint velocities (default: zero).
    #[arg(long, value_parser = parse_number_list, allow_hyphen_values = true)]
    qd0: Option<NumberList>,
    /// Largest RK4 step, s.
    #[arg(long, default_value_t = 1e-3)]
    max_step: f64,
    /// Joint end stops in the plant at the description's limits (the run must then start
    /// inside them, e.g. `--q0 0,0,0.2,0` for the SCARA).
    #[arg(long)]
    end_stops: bool,
    #[command(flatten)]
    limit: StepLimit,
}

/// Runs `armdyn simulate`.
pub fn run(args: &SimulateArgs) -> anyhow::Result<()> {
    armdyn::with_robot_named!(args.robot.as_str(), |robot: R, N, _module| {
        simulate::<N, R>(args, &robot)
    })
    .with_context(|| format!("unknown robot '{}'", args.robot))?
}

fn simulate<const N: usize, R: RobotModel<N>>(
    args: &SimulateArgs,
    robot: &R,
) -> anyhow::Result<()> {
    let path = args.torque_csv.display().to_string();
    let file =
        std::fs::File::open(&args.torque_csv).with_context(|| format!("cannot read {path}"))?;
    let history = TorqueHistory::<N>::from_csv_reader(std::io::BufReader::new(file))
        .with_context(|| format!("{path} (robot {}, {N} joints)", R::NAME))?;
    let times = history.times();
    let q0 =
        JointVector::<N>::from_column_slice(&joint_list("--q0", R::NAME, N, args.q0.as_ref())?);
    let qd0 =
        JointVector::<N>::from_column_slice(&joint_list("--qd0", R::NAME, N, args.qd0.as_ref())?);
    let stops = args.end_stops.then(|| EndStops::from_model(robot));
    if stops.is_some() {
        let (lo, hi) = (robot.lower_limits(), robot.upper_limits());
        if let Some(i) = (0..N).find(|&i| !(lo[i] <= q0[i] && q0[i] <= hi[i])) {
            anyhow::bail!(
                "--q0: joint {} = {} is outside its limits [{:.4}, {:.4}]; with --end-stops the run must start inside them",
                i + 1,
                q0[i],
                lo[i],
                hi[i]
            );
        }
    }
    let (first, last) = (times[0], times[times.len() - 1]);
    args.limit.check(
        &path,
        plant_steps(times, args.max_step),
        &format!(
            "t from {} to {} s in steps of at most {} s",
            num(first),
            num(last),
            num(args.max_step)
        ),
    )?;
    let mut out = String::from("t");
    for prefix in ["q", "qd"] {
        for i in 1..=N {
            out += &format!(",{prefix}{i}");
        }
    }
    out.push('\n');
    let mut progress = Progress::start(&path, first, last);
    simulate_torques(
        robot,
        times,
        history.torques(),
        &q0,
        &qd0,
        args.max_step,
        stops.as_ref(),
        |t, q, qd| {
            use std::fmt::Write;
            let _ = write!(out, "{t:?}");
            for x in q.iter().chain(qd.iter()) {
                let _ = write!(out, ",{x:?}");
            }
            out.push('\n');
        },
        |t| progress.step(t),
    )
    .context("simulation stopped; no files were written")?;
    progress.finish();
    let mut dir = OutputDir::create(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    dir.write("trajectory.csv", out)?;
    dir.commit()?;
    outln!(
        "simulated {} samples; wrote {}",
        times.len(),
        args.out.join("trajectory.csv").display()
    );
    Ok(())
}
