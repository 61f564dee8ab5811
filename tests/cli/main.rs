//! Tests of the `armdyn` command line end to end: outputs, and errors on bad input with nothing written.
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

mod any_robot;
mod closed_stdout;
#[path = "../common/command.rs"]
mod command;
mod common;
mod design;
mod identify_log;
mod identify_sweep;
mod model;
mod plan;
mod run;
#[path = "../common/scratch.rs"]
mod scratch;
