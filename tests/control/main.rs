//! Tests of `armdyn::control`: gain designs, poles and Riccati residuals, and the force-loop
//! design (`gains`, `force_design`, `design`); the force laws on their own (`hybrid`,
//! `impedance`, `task_space`, `selection`, `normal_reading`, `tool_compensation`, and a
//! user's own law, `own_force_law`); the safety checks (`safety`). A file here tests the file
//! of the same name in `src/control/`.
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

mod design;
mod force_design;
mod gains;
mod hybrid;
mod impedance;
mod normal_reading;
mod own_force_law;
mod safety;
mod selection;
mod task_space;
mod tool_compensation;
