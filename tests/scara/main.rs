//! Tests of the SCARA's own code (`armdyn::robots::scara`): the thesis's numbers, its trials, the workspace and elbow planning, elbow flips and the deployable step.
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

#[macro_use]
#[path = "../common/mod.rs"]
mod common;
mod deploy_hybrid;
mod elbow_flip;
mod elbow_plan;
mod hybrid_trials;
mod joint_target;
mod kinematics_workspace;
mod position_trials;
mod thesis;
mod thesis_setup;
mod trials;
mod workspace;
