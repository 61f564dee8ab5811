//! Tests of `armdyn::scenario`: the file format and its errors, the thesis and contact scenarios, any robot of the registry, joint references and plant mismatch.
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

mod any_robot;
#[path = "../common/command.rs"]
mod command;
mod contact;
mod faults;
mod files;
mod joint_reference;
mod linearize;
mod model_mismatch;
#[path = "../common/properties.rs"]
mod properties;
#[path = "../common/scratch.rs"]
mod scratch;
mod six_d;
mod six_d_laws;
mod start;
mod stepped;
mod thesis;
mod tool_sensor;
