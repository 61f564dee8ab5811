//! `armdyn urdf`: a robot of the project as a URDF, for Pinocchio, MuJoCo, RViz and ROS.

use std::path::PathBuf;

use anyhow::Context;
use clap::Args;

use crate::cli_args::robot_parser;

/// Arguments of `armdyn urdf`.
#[derive(Debug, Args)]
pub struct UrdfArgs {
    /// Robot to write (any generated robot, DH ones included).
    #[arg(long, value_parser = robot_parser())]
    robot: String,
    /// Write the URDF to this file (atomically) instead of printing it.
    #[arg(long, value_name = "FILE")]
    out: Option<PathBuf>,
}

/// The URDF text of a generated robot (written by the generator beside its model; each link in
/// its joint frame, inertia about the COM; gravity in a comment, as URDF has no field for it).
pub fn urdf_of(name: &str) -> Option<&'static str> {
    armdyn::with_robot_named!(name, |_robot: R, N, module| module::URDF)
}

/// Runs `armdyn urdf`.
pub fn run(args: &UrdfArgs) -> anyhow::Result<()> {
    let text = urdf_of(&args.robot).with_context(|| format!("unknown robot '{}'", args.robot))?;
    match &args.out {
        None => out!("{text}"),
        Some(path) => armdyn::report::write_atomic(path, text.as_bytes())
            .with_context(|| format!("writing {}", path.display()))?,
    }
    Ok(())
}
