//! Tests of `armdyn::identification`: base parameters of every robot and identification on
//! the simulated plant (`base_parameters`), the log reader on edited and random input
//! (`log`), identification from a log (`from_log`), and a log like a real robot's
//! (`real_log`).
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

mod base_parameters;
mod from_log;
mod log;
#[path = "../common/properties.rs"]
mod properties;
mod real_log;
#[path = "../common/scratch.rs"]
mod scratch;
