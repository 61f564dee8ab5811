//! Tests of `armdyn::identification`: base parameters of every robot and identification on
//! the simulated plant (`base_parameters`), the log reader on edited and random input
//! (`log_repairs`, `log`), identification from a log (`from_log`), a log like a real robot's
//! (`real_log`), resampling (`resample`), the least-squares solver (`nonlinear`) and the
//! physically consistent fit (`physical`).
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

mod base_parameters;
mod from_log;
mod log;
mod log_repairs;
mod nonlinear;
mod physical;
#[path = "../common/properties.rs"]
mod properties;
mod real_log;
mod resample;
#[path = "../common/scratch.rs"]
mod scratch;
