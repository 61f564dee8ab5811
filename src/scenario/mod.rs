//! The thesis's trials, assembled from the library's pieces (std only): reference sources
//! for the SCARA, the controller line-up of Chapters 4 and 5, and a runner that records
//! every sample.

mod controllers;
mod deployed;
mod embedded;
mod error;
pub mod file;
mod force_design;
mod law_spec;
mod output;
pub mod plant;

mod runner;
mod spec;
mod trial;

pub use crate::robots::scara::reference::{DesiredForce, ForceShape, ScaraReference};
pub use controllers::{
    ForceController, ForceReference, GainReport, HybridSetup, PositionController, UnknownName,
};
pub use deployed::prepare_deployed;
pub use embedded::{built_in, BUILT_IN};
pub use error::{line_of, ScenarioError};
pub use force_design::{contact_model, ContactModel};
pub use law_spec::{GainChoice, LawChoice, DEFAULT_BANDWIDTH_HZ, DEFAULT_DAMPING};
pub use output::{metrics_json, output_names, write_outputs};
pub use plant::{ControllerModel, PlantSpec};
pub use runner::{run, RunOutput};
pub use spec::{
    AdmittanceSettings, DesignSettings, ForceReferenceSpec, ForceSpec, ImpedanceSettings,
    LawSettings, ReferenceSpec, Scenario, SensorSpec, ThesisReference,
};
pub use trial::{
    execute, prepare, run_duration, shifted, Outcome, Prepared, MAX_REACH_GAP_M, TRACKING_AFTER_S,
};
