//! Tests of the `armdyn` command line end to end: outputs, and errors on bad input with nothing written.
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

mod cli_any_robot;
mod cli_closed_stdout;
mod cli_design;
mod cli_identify_log;
mod cli_identify_sweep;
mod cli_model;
mod cli_plan;
mod cli_run;
mod common;
