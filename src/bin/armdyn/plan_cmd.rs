//! `armdyn plan`: the minimum-effort joint move of any robot between two configurations at
//! rest in a given time, or the shortest one within an effort share (control-limited iLQR on
//! the generated derivatives, `armdyn::optimal`), compared with the quintic of the same
//! duration and the shortest quintic within the same share.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::Context;
use clap::Args;
use serde_json::json;

use armdyn::model::JointVector;
use armdyn::optimal::{
    optimise_move, quintic_effort, quintic_peak_effort_share, shortest_move, shortest_quintic,
    IlqrOptions, MoveProblem, OptimalMove,
};
use armdyn::report::atomic::write_atomic;
use armdyn::scenario::ScenarioRobot;

use crate::cli_args::{joint_values, parse_number_list, robot_parser, NumberList};
use crate::json_out::to_json;

/// Arguments of `armdyn plan`.
#[derive(Debug, Args)]
pub struct PlanArgs {
    /// Robot (any generated robot).
    #[arg(long, value_parser = robot_parser(), default_value = "scara")]
    robot: String,
    /// Start configuration, at rest: one value per joint, comma-separated (rad or m).
    #[arg(long, value_name = "V1,V2,..", allow_hyphen_values = true, value_parser = parse_number_list)]
    from: NumberList,
    /// Goal configuration, at rest: one value per joint (rad or m).
    #[arg(long, value_name = "V1,V2,..", allow_hyphen_values = true, value_parser = parse_number_list)]
    to: NumberList,
    /// Duration of the move, s: the minimum-effort move in this time.
    #[arg(
        long,
        value_name = "S",
        required_unless_present = "shortest",
        conflicts_with = "shortest"
    )]
    duration: Option<f64>,
    /// The shortest move within the effort share instead of a given duration.
    #[arg(long)]
    shortest: bool,
    /// Largest share of each actuator's effort limit any torque may use, in (0, 1].
    #[arg(long, value_name = "SHARE", default_value_t = 1.0)]
    effort_share: f64,
    /// Knot spacing of the plan, s (torque and acceleration held over each step).
    #[arg(long, value_name = "S", default_value_t = 0.005)]
    step: f64,
    /// RK4 steps per knot step (the torque held over the knot step).
    #[arg(long, value_name = "K", default_value_t = 1)]
    substeps: usize,
    /// How far inside each joint limit the move stays, rad or m.
    #[arg(long, value_name = "M", default_value_t = 0.0)]
    limit_margin: f64,
    /// Largest joint speeds, one per joint, comma-separated (rad/s or m/s; default none).
    #[arg(long, value_name = "V1,V2,..", value_parser = parse_number_list)]
    max_speed: Option<NumberList>,
    /// Write the plan as CSV: `t`, then `q_`, `qd_`, `qdd_`, `tau_` per joint, one row per
    /// knot (the last row's torque holds the goal against gravity).
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// Print one JSON object instead of the summary.
    #[arg(long)]
    json: bool,
}

/// The plan's knots as CSV text.
fn csv_text<const N: usize, R: ScenarioRobot<N>>(robot: &R, m: &OptimalMove<N>) -> String {
    let mut out = String::from("t");
    for prefix in ["q", "qd", "qdd", "tau"] {
        for j in R::JOINT_NAMES {
            let _ = write!(out, ",{prefix}_{j}");
        }
    }
    out.push('\n');
    let steps = m.qdd.len();
    let hold = robot.gravity(&m.q[steps]);
    for k in 0..=steps {
        let (qdd, tau) = if k < steps {
            (m.qdd[k], m.tau[k])
        } else {
            (JointVector::<N>::zeros(), hold)
        };
        let _ = write!(out, "{:?}", k as f64 * m.step_s);
        for v in [&m.q[k], &m.qd[k], &qdd, &tau] {
            for x in v.iter() {
                let _ = write!(out, ",{x:?}");
            }
        }
        out.push('\n');
    }
    out
}

fn plan<const N: usize, R: ScenarioRobot<N>>(robot: &R, a: &PlanArgs) -> anyhow::Result<()> {
    let from = JointVector::<N>::from(joint_values::<N>("--from", R::NAME, Some(&a.from))?);
    let to = JointVector::<N>::from(joint_values::<N>("--to", R::NAME, Some(&a.to))?);
    let problem = MoveProblem {
        from,
        to,
        duration_s: a.duration.unwrap_or(1.0),
        step_s: a.step,
        substeps: a.substeps,
        max_effort_share: a.effort_share,
        limit_margin: a.limit_margin,
        max_joint_speed: a
            .max_speed
            .as_ref()
            .map(|l| joint_values::<N>("--max-speed", R::NAME, Some(l)).map(JointVector::<N>::from))
            .transpose()?,
    };
    let options = IlqrOptions::default();
    let started = Instant::now();
    let m = if a.shortest {
        shortest_move(robot, &problem, &options)
    } else {
        optimise_move(robot, &problem, &options)
    }
    .with_context(|| format!("planning the move of {}", R::NAME))?;
    let solve_s = started.elapsed().as_secs_f64();
    let duration = m.duration_s();
    let quintic_share = quintic_peak_effort_share(robot, &from, &to, duration);
    let quintic_spent = quintic_effort(robot, &from, &to, duration);
    let quintic_shortest = shortest_quintic(robot, &from, &to, a.effort_share).ok();
    let e = robot.effort_limits();
    let per_joint: Vec<f64> = (0..N)
        .map(|i| {
            m.tau
                .iter()
                .map(|t| (t[i] / e[i]).abs())
                .fold(0.0, f64::max)
        })
        .collect();
    let peak_joint = (0..N)
        .max_by(|&x, &y| per_joint[x].total_cmp(&per_joint[y]))
        .unwrap_or(0);
    if let Some(path) = &a.csv {
        write_atomic(path, csv_text(robot, &m))
            .with_context(|| format!("writing the plan to {}", path.display()))?;
    }
    if a.json {
        let value = json!({
            "robot": R::NAME,
            "objective": if a.shortest { "shortest" } else { "minimum-effort" },
            "duration_s": duration,
            "step_s": m.step_s,
            "effort_share_limit": a.effort_share,
            "effort_s": m.effort,
            "peak_effort_share": m.peak_effort_share,
            "peak_effort_share_per_joint": per_joint,
            "violation": m.violation,
            "iterations": m.iterations,
            "solve_time_s": solve_s,
            "quintic_peak_effort_share_same_duration": quintic_share,
            "quintic_effort_s_same_duration": quintic_spent,
            "quintic_shortest_duration_s": quintic_shortest,
        });
        outln!("{}", to_json(&value, false));
        return Ok(());
    }
    let what = if a.shortest {
        format!(
            "shortest move within {:.0} % of each effort limit",
            100.0 * a.effort_share
        )
    } else {
        "minimum-effort move".into()
    };
    outln!(
        "{}: {what}, {duration:.4} s ({} steps of {:.1} ms)",
        R::NAME,
        m.qdd.len(),
        1e3 * m.step_s
    );
    outln!(
        "  peak effort share {:.1} % (joint {}); the quintic of the same duration: {:.1} %",
        100.0 * m.peak_effort_share,
        R::JOINT_NAMES[peak_joint],
        100.0 * quintic_share
    );
    outln!(
        "  effort, integral of sum (tau_i / e_i)^2 dt: {:.5} s; the quintic's: {quintic_spent:.5} s",
        m.effort
    );
    if let Some(q) = quintic_shortest {
        outln!(
            "  shortest quintic within {:.0} %: {q:.4} s (this move: {:.2} of it)",
            100.0 * a.effort_share,
            duration / q
        );
    }
    outln!(
        "  goal error {:.1e}, {} iterations, {:.2} s to solve",
        m.violation,
        m.iterations,
        solve_s
    );
    if let Some(path) = &a.csv {
        outln!("  plan written to {}", path.display());
    }
    Ok(())
}

/// Runs `armdyn plan`.
pub fn run(args: &PlanArgs) -> anyhow::Result<()> {
    armdyn::with_robot_named!(args.robot.as_str(), |robot: R, N, _module| {
        plan(&robot, args)
    })
    .with_context(|| format!("unknown robot '{}'", args.robot))?
}
