//! Tests of `armdyn::control`: gain designs, poles and Riccati residuals, and the force-loop design.
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

mod force_design;
mod gains;
mod own_force_law;
