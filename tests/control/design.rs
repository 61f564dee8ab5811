//! Tests of `armdyn::control::design`: the actuator, the loop model, its analysis and pole placement.

mod actuator;
mod analysis;
mod loop_model;
mod placement;
