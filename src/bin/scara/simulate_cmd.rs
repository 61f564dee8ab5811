//! `scara simulate --torque-csv FILE --out DIR`: open-loop simulation of the SCARA.

use std::path::PathBuf;

use anyhow::Context;
use clap::Args;
use nalgebra::Vector4;

use scara::model::RobotModel;
use scara::model::Scara;
use scara::report::OutputDir;
use scara::sim::open_loop::{plant_steps, simulate_torques_reporting};
use scara::sim::torque_history::TorqueHistory;
use scara::sim::EndStops;

use crate::cli_args::{joint_values, parse_number_list, NumberList};
use crate::progress::{num, Progress, StepLimit};

/// Arguments of `scara simulate`.
#[derive(Debug, Args)]
pub struct SimulateArgs {
    /// Torques: CSV with header `t,tau1,tau2,tau3,tau4` (s, N m, N m, N, N m), strictly
    /// increasing t; each row is held until the next one. UTF-8, with or without a
    /// byte-order mark, LF or CRLF line ends.
    #[arg(long, value_name = "FILE")]
    torque_csv: PathBuf,
    /// Output folder; gets `trajectory.csv` (`t,q1,q2,q3,q4,qd1,qd2,qd3,qd4`).
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
    /// inside them, e.g. `--q0 0,0,0.2,0`).
    #[arg(long)]
    end_stops: bool,
    #[command(flatten)]
    limit: StepLimit,
}

/// Runs `scara simulate`.
pub fn run(args: &SimulateArgs) -> anyhow::Result<()> {
    let path = args.torque_csv.display().to_string();
    let file =
        std::fs::File::open(&args.torque_csv).with_context(|| format!("cannot read {path}"))?;
    let history = TorqueHistory::<4>::from_csv_reader(std::io::BufReader::new(file))
        .with_context(|| path.clone())?;
    let times = history.times();
    let q0: [f64; 4] = joint_values::<4>("--q0", "scara", args.q0.as_ref())?;
    let qd0: [f64; 4] = joint_values::<4>("--qd0", "scara", args.qd0.as_ref())?;
    let stops = args.end_stops.then(|| EndStops::from_model(&Scara));
    if stops.is_some() {
        let (lo, hi) = (Scara.lower_limits(), Scara.upper_limits());
        if let Some(i) = (0..4).find(|&i| !(lo[i] <= q0[i] && q0[i] <= hi[i])) {
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
    let mut out = String::from("t,q1,q2,q3,q4,qd1,qd2,qd3,qd4\n");
    let mut progress = Progress::start(&path, first, last);
    simulate_torques_reporting(
        &Scara,
        times,
        history.torques(),
        &Vector4::from(q0),
        &Vector4::from(qd0),
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
