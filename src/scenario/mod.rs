//! Scenarios (std only): a whole trial as a checked file ([`Scenario`]), prepared for its
//! robot as one-way stages ([`stages`]: reference, plant, position law, force law, sensor)
//! and run ([`execute`]) with every sample recorded and its metrics; for any robot of the
//! registry (found by name with [`with_robot_named!`](crate::with_robot_named)), with a
//! robot's own knowledge reached through
//! [`ScenarioRobot`].

mod check;
mod controllers;
mod deployed;
mod desired_force;
mod embedded;
mod error;
mod execute;
pub mod fault_spec;
pub mod file;
mod force_spec;
pub mod ik_plan;
pub mod joint_plan;
mod law_spec;
pub mod linearize;
mod outcome;
mod output;
mod planned;
pub mod plant;
mod prepare;
mod reference_spec;
pub mod robot;
mod runner;
pub mod safety_outcome;
pub mod safety_spec;
mod spec;
pub mod stages;
mod stepped;
mod surface_spec;
pub(crate) mod toml_table;
mod view_file;
pub mod vocabulary;

pub use controllers::{
    pid_report, ForceController, GainReport, PositionController, PositionSettings, UnknownName,
    PID_POLES, POSTURE_OMEGA, TASK_SPACE_OMEGA,
};
pub use deployed::{prepare_deployed, prepare_deployed_for};
pub use desired_force::{DesiredForce, ForceShape};
pub use embedded::{built_in, BUILT_IN};
pub use error::{line_of, ScenarioError};
pub use execute::execute;
pub use law_spec::{GainChoice, LawChoice, DEFAULT_BANDWIDTH_HZ, DEFAULT_DAMPING};
pub use outcome::{JointTracking, Outcome, Recorded, RunCounts, TRACKING_AFTER_S};
pub use output::{metrics_json, output_names, units, write_outputs_for};
pub use planned::{PlannedReference, ReferenceReport, SharedTrajectory};
pub use plant::{ControllerModel, PlantSpec};
pub use prepare::{prepare, prepare_for, run_duration, Prepared, PreparedRun};
pub use robot::{Precision, ScenarioRobot};
pub use runner::{run, RunOutput};
pub use spec::{
    controller_model_for, AdmittanceSettings, DesignSettings, ForceReferenceSpec, ForceSpec,
    IkSettings, ImpedanceSettings, LawSettings, ReferenceSpec, Scenario, SensorSpec,
};
pub use stages::force_design::{contact_model, ContactModel};
pub use stages::force_law::MAX_REACH_GAP_M;
pub use stepped::{Mode, StepOutcome, SteppedController};
pub use view_file::write_view;
pub use vocabulary::RobotVocabulary;
