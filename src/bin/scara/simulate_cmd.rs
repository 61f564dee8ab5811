//! `scara simulate --torque-csv FILE --out DIR`: open-loop simulation of the SCARA.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context};
use clap::Args;
use nalgebra::Vector4;

use scara::model::RobotModel;
use scara::model::Scara;
use scara::report::OutputDir;
use scara::sim::open_loop::simulate_torques_with_stops;
use scara::sim::EndStops;

use crate::cli_args::{joint_values, parse_number_list, NumberList};

/// Arguments of `scara simulate`.
#[derive(Debug, Args)]
pub struct SimulateArgs {
    /// Torques: CSV with header `t,tau1,tau2,tau3,tau4` (s, N m, N m, N, N m), strictly
    /// increasing t; each row is held until the next one.
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
}

/// Runs `scara simulate`.
pub fn run(args: &SimulateArgs) -> anyhow::Result<()> {
    let text = std::fs::read_to_string(&args.torque_csv)
        .with_context(|| format!("cannot read {}", args.torque_csv.display()))?;
    let (times, torques) = parse_torques(&text, &args.torque_csv)?;
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
    let mut out = String::from("t,q1,q2,q3,q4,qd1,qd2,qd3,qd4\n");
    simulate_torques_with_stops(
        &Scara,
        &times,
        &torques,
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
    )
    .context("simulation stopped; no files were written")?;
    let mut dir = OutputDir::create(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    dir.write("trajectory.csv", out)?;
    dir.commit()?;
    println!(
        "simulated {} samples; wrote {}",
        times.len(),
        args.out.join("trajectory.csv").display()
    );
    Ok(())
}

/// Parses `t,tau1,tau2,tau3,tau4`; errors name the file, line and column.
fn parse_torques(text: &str, path: &Path) -> anyhow::Result<(Vec<f64>, Vec<Vector4<f64>>)> {
    const HEADER: [&str; 5] = ["t", "tau1", "tau2", "tau3", "tau4"];
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let Some((_, header)) = lines.next() else {
        bail!(
            "{}: empty file; expected the header `t,tau1,tau2,tau3,tau4`",
            path.display()
        );
    };
    let cols: Vec<&str> = header.split(',').map(str::trim).collect();
    for name in HEADER {
        if !cols.contains(&name) {
            bail!(
                "{}: line 1: missing column `{name}` (header must be `t,tau1,tau2,tau3,tau4`)",
                path.display()
            );
        }
    }
    if cols.len() != HEADER.len() {
        bail!(
            "{}: line 1: expected exactly the columns t,tau1,tau2,tau3,tau4, got `{header}`",
            path.display()
        );
    }
    let index: Vec<usize> = HEADER
        .iter()
        .map(|h| cols.iter().position(|c| c == h).unwrap_or(0))
        .collect();
    let (mut times, mut torques) = (Vec::new(), Vec::new());
    for (i, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != HEADER.len() {
            bail!(
                "{}: line {}: expected {} values, got {}",
                path.display(),
                i + 1,
                HEADER.len(),
                fields.len()
            );
        }
        let mut v = [0.0; 5];
        for (k, &col) in index.iter().enumerate() {
            let x: f64 = fields[col].parse().map_err(|_| {
                anyhow::anyhow!(
                    "{}: line {}, column `{}`: `{}` is not a number",
                    path.display(),
                    i + 1,
                    HEADER[k],
                    fields[col]
                )
            })?;
            if !x.is_finite() {
                bail!(
                    "{}: line {}, column `{}`: value must be finite, got {x}",
                    path.display(),
                    i + 1,
                    HEADER[k]
                );
            }
            v[k] = x;
        }
        if let Some(&last) = times.last() {
            if v[0] <= last {
                bail!("{}: line {}: time {} is not after the previous time {last}; times must increase", path.display(), i + 1, v[0]);
            }
        }
        times.push(v[0]);
        torques.push(Vector4::new(v[1], v[2], v[3], v[4]));
    }
    if times.is_empty() {
        bail!("{}: no data rows after the header", path.display());
    }
    Ok((times, torques))
}
