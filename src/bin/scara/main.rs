//! `scara`: command-line front end of the `scara` crate.
//!
//! One file per subcommand; `main` only parses and dispatches. To add a subcommand, add a
//! module with an `Args` struct (clap derive) and a `run(args) -> anyhow::Result<()>`, and
//! a variant to [`Command`].

mod cli_args;
mod json_out;
mod model_cmd;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Model-based control of robot arms: generated dynamics, controllers and simulation.
#[derive(Debug, Parser)]
#[command(name = "scara", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Print the pose, Jacobian, M, C, c and g of a robot at (q, qd) as one JSON object.
    Model(model_cmd::ModelArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Model(args) => model_cmd::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::FAILURE
        }
    }
}
