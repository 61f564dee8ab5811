//! `armdyn`: command-line front end of the `armdyn` crate.
//!
//! One file per subcommand; `main` only parses and dispatches. To add a subcommand, add a
//! module with an `Args` struct (clap derive) and a `run(args) -> anyhow::Result<()>`, and
//! a variant to [`Command`].

/// `println!` for the command's output: when stdout is closed early (`armdyn ... | head`) the
/// program ends quietly with success instead of panicking; any other failure to write is
/// reported on stderr and ends it with failure.
macro_rules! outln {
    () => {
        $crate::write_stdout(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::write_stdout(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// `print!` counterpart of [`outln!`].
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::write_stdout(format_args!($($arg)*))
    };
}

mod cli_args;
mod design_cmd;
mod identify_cmd;
mod identify_companions;
mod identify_log_cmd;
mod joint_trial;
mod json_out;
mod law_table;
mod linearize_cmd;
mod model_cmd;
mod plan_cmd;
mod precision;
mod progress;
mod run_cmd;
mod simulate_cmd;
mod stage_progress;
mod sweep_cmd;
mod urdf_cmd;
mod view_cmd;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Model-based control of robot arms: generated dynamics, controllers and simulation.
#[derive(Debug, Parser)]
#[command(name = "armdyn", version, about)]
struct Cli {
    /// Without a subcommand: the thesis's hybrid force/position trial (PI + feedforward +
    /// velocity damping, constant -200 N), written to `out/hybrid/`.
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Design or analyse controller gains (`design force`: the force loop along the normal).
    Design(design_cmd::DesignArgs),
    /// Print the pose, Jacobian, M, C, c and g of a robot at (q, qd) as one JSON object.
    Model(model_cmd::ModelArgs),
    /// Optimise a joint move of any robot: minimum effort in a given time, or the shortest
    /// within an effort share (iLQR with torque and joint limits).
    Plan(plan_cmd::PlanArgs),
    /// Run one of the thesis's trials (or all controllers of one) and write CSV, metrics, plots.
    Run(run_cmd::RunArgs),
    /// Open-loop simulation of a robot (the SCARA by default) from a torque CSV
    /// (`t,tau1,...,tauN`).
    Simulate(simulate_cmd::SimulateArgs),
    /// Identify a robot's base parameters on its simulated plant; write identification.json.
    Identify(identify_cmd::IdentifyArgs),
    /// Monte Carlo sweep of a scenario's [sweep] distributions, trials in parallel.
    Sweep(sweep_cmd::SweepArgs),
    /// Print (or write with --out) a robot of the project as a URDF.
    Urdf(urdf_cmd::UrdfArgs),
    /// Write the 3-D viewer (`view.html`) of existing run output folders again.
    View(view_cmd::ViewArgs),
}

/// Writes to stdout; see [`outln!`].
fn write_stdout(text: std::fmt::Arguments<'_>) {
    use std::io::Write as _;
    if let Err(err) = std::io::stdout().lock().write_fmt(text) {
        if err.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("error: writing to stdout: {err}");
        std::process::exit(1);
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Some(Command::Design(args)) => design_cmd::run(&args),
        Some(Command::Model(args)) => model_cmd::run(&args),
        Some(Command::Plan(args)) => plan_cmd::run(&args),
        Some(Command::Run(args)) => run_cmd::run_cmd(&args),
        Some(Command::Simulate(args)) => simulate_cmd::run(&args),
        Some(Command::Identify(args)) => identify_cmd::run(&args),
        Some(Command::Sweep(args)) => sweep_cmd::run(&args),
        Some(Command::Urdf(args)) => urdf_cmd::run(&args),
        Some(Command::View(args)) => view_cmd::run(&args),
        None => run_cmd::hybrid(&run_cmd::HybridArgs::default_trial()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::FAILURE
        }
    }
}
