//! `armdyn model`: the robot's kinematics and dynamics at one state, as JSON.

use anyhow::Context;
use armdyn::model::{JointVector, RobotModel};
use clap::Args;
use nalgebra::SMatrix;
use serde::Serialize;

use crate::cli_args::{joint_values, parse_number_list, robot_parser, NumberList};
use crate::json_out::to_json;

/// Arguments of `armdyn model`.
#[derive(Debug, Args)]
pub struct ModelArgs {
    /// Robot to evaluate (any generated robot).
    #[arg(long, value_parser = robot_parser(), default_value = "scara")]
    robot: String,
    /// Joint positions, comma-separated (rad or m); one per joint, default all zero.
    #[arg(long, value_name = "V1,V2,..", allow_hyphen_values = true, value_parser = parse_number_list)]
    q: Option<NumberList>,
    /// Joint velocities, comma-separated (rad/s or m/s); one per joint, default all zero.
    #[arg(long, value_name = "V1,V2,..", allow_hyphen_values = true, value_parser = parse_number_list)]
    qd: Option<NumberList>,
    /// Print on one line (default: indented, one matrix row per line).
    #[arg(long)]
    compact: bool,
}

/// The printed object. Matrices are row-major nested arrays; SI units throughout.
#[derive(Debug, Serialize)]
struct ModelReport {
    robot: &'static str,
    q: Vec<f64>,
    qd: Vec<f64>,
    /// End-effector pose in the base frame, 4 x 4 homogeneous (m).
    pose: Vec<Vec<f64>>,
    /// Geometric Jacobian, 6 x n, base frame, rows vx vy vz wx wy wz.
    jacobian: Vec<Vec<f64>>,
    mass_matrix: Vec<Vec<f64>>,
    coriolis_matrix: Vec<Vec<f64>>,
    /// The velocity term `c = C(q, qd) qd`.
    coriolis: Vec<f64>,
    gravity: Vec<f64>,
}

fn rows<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> Vec<Vec<f64>> {
    m.row_iter()
        .map(|row| row.iter().copied().collect())
        .collect()
}

fn report<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &Option<NumberList>,
    qd: &Option<NumberList>,
) -> anyhow::Result<ModelReport> {
    let q = JointVector::<N>::from(joint_values::<N>("--q", R::NAME, q.as_ref())?);
    let qd = JointVector::<N>::from(joint_values::<N>("--qd", R::NAME, qd.as_ref())?);
    Ok(ModelReport {
        robot: R::NAME,
        q: q.iter().copied().collect(),
        qd: qd.iter().copied().collect(),
        pose: rows(&robot.end_effector_pose(&q)),
        jacobian: rows(&robot.jacobian(&q)),
        mass_matrix: rows(&robot.mass_matrix(&q)),
        coriolis_matrix: rows(&robot.coriolis_matrix(&q, &qd)),
        coriolis: robot.coriolis(&q, &qd).iter().copied().collect(),
        gravity: robot.gravity(&q).iter().copied().collect(),
    })
}

/// Runs `armdyn model`: prints one JSON object on standard output.
pub fn run(args: &ModelArgs) -> anyhow::Result<()> {
    let report = armdyn::with_robot_named!(args.robot.as_str(), |robot: R, N, _module| {
        report(&robot, &args.q, &args.qd)
    })
    .with_context(|| format!("unknown robot '{}'", args.robot))??;
    let value = serde_json::to_value(&report).context("serialising the model report")?;
    outln!("{}", to_json(&value, args.compact));
    Ok(())
}
